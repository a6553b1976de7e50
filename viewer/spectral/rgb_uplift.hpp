// RGB to spectrum after Jakob & Hanika 2019 ("A Low-Dimensional Function Space for Efficient
// Spectral Upsampling", Computer Graphics Forum 38(2)): a colour becomes the reflectance
//     ρ(λ) = S(c0 t² + c1 t + c2),  S(x) = ½ + x / (2 √(1 + x²)),  t = (λ - 360 nm) / 470 nm,
// smooth and within [0, 1], whose colour under D65 is the linear sRGB colour asked for. The
// coefficients are fitted by Gauss-Newton in CIELAB (their rgb2spec_opt, as pbrt-v4 ships it) over a
// grid of the RGB cube, once, at build time (fxview-uplift-table writes the table that
// srgb_uplift_table() returns); a lookup interpolates them trilinearly.
// A radiance (an environment's texel, unbounded) becomes L(λ) = 2m ρ(λ) D65(λ) with ρ the
// reflectance of rgb / 2m, m its largest channel (pbrt-v4's RGBIlluminantSpectrum).
// Our colorimetry throughout: CIE 1931 at 1 nm over 360-830 nm, D65 = CIE daylight at 6504 K scaled
// to luminance 1 (constant 1 has Y = 1, spectral/colorimetry.hpp), linear sRGB by eq. 9's matrix.
#pragma once
#include <array>
#include <vector>

#include "spectral/colorimetry.hpp"

namespace fxview::spectral {

struct SigmoidPolynomial {
    double c0 = 0.0, c1 = 0.0, c2 = 0.0;  // in t = (nm - 360) / 470
    double operator()(double nm) const;
};

class UpliftFit {
public:
    static constexpr int kFirstNm = 360, kLastNm = 830;
    explicit UpliftFit(const Observer& observer);

    Vec3 rgb(const SigmoidPolynomial& reflectance) const;  // linear sRGB of the reflectance lit by D65
    Vec3 lab(const SigmoidPolynomial& reflectance) const;  // its CIELAB, white D65
    Vec3 lab_of_rgb(const Vec3& rgb) const;
    // Gauss-Newton from `start` (at most 15 steps, as rgb2spec_opt); `residual` gets the CIELAB
    // distance left (ΔE*ab).
    SigmoidPolynomial fit(const Vec3& rgb, SigmoidPolynomial start, double* residual = nullptr) const;
    // D65 of luminance 1, 360-830 nm at 1 nm.
    const std::vector<double>& illuminant() const { return illuminant_; }

private:
    std::vector<double> illuminant_;
    std::vector<double> t_;                        // per nm
    std::array<std::vector<double>, 3> to_xyz_;    // per nm: cmf × D65 / Σ ȳ
    Vec3 white_{};
};

struct UpliftTable {
    int resolution = 0;
    std::vector<float> scale;         // the largest channel's value at each of `resolution` nodes
    std::vector<float> coefficients;  // [largest channel][scale node][y][x][c0 c1 c2]
    // The largest ΔE*ab any node's fit left, per scale node. The darkest nodes cannot reach their
    // colour within the bounded coefficients (a saturated colour of luminance 1e-4) and do not matter
    // to the eye; node 0 (black) holds node 1's coefficients.
    std::vector<double> worst_residual;

    // rgb in [0, 1]³ (clamped); a grey is the exact constant.
    SigmoidPolynomial lookup(const Vec3& rgb) const;
};

// Fits every node, in parallel: along the brightness axis each node starts from the last one's
// coefficients, from a fifth of the scale outwards (as rgb2spec_opt).
UpliftTable make_uplift_table(const UpliftFit& fit, int resolution);

// The table generated at build time for this colorimetry (fxview_uplift_table).
const UpliftTable& srgb_uplift_table();

// A radiance's spectrum: value(nm) = scale × shape(nm) × D65(nm).
struct UpliftedRadiance {
    double scale = 0.0;
    SigmoidPolynomial shape;
    double value(int nm, const std::vector<double>& illuminant) const {
        return scale == 0.0 ? 0.0 : scale * shape(nm) * illuminant[static_cast<size_t>(nm - UpliftFit::kFirstNm)];
    }
};
// Negative channels count as 0 (out of gamut: sRGB cannot hold it, nor can a reflectance).
UpliftedRadiance uplift_radiance(const Vec3& rgb, const UpliftTable& table = srgb_uplift_table());

}  // namespace fxview::spectral
