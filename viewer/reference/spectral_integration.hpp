// What every spectral reference shares with effects/lib/spectral.glsl: the CMF and spectrum textures
// the GPU samples, the integration range and k, and XYZ -> linear sRGB (eq. 9) with the chosen gamut
// mapping. The references weigh each wavelength themselves.
#pragma once
#include <algorithm>
#include <array>

#include "reference/reference.hpp"
#include "spectral/colorimetry.hpp"
#include "spectral/packing.hpp"

namespace fxview::reference {

struct SpectralSetup {
    const spectral::PackedTexture* cmf;
    const spectral::PackedTexture* spectra;
    int observer, lower, upper, steps, mapping;
    double cmf_unit;  // the GPU reads stored values: 8-bit CMFs are divided by their scale
    double k, brightness;
};

// Reads ByteCmf, Observer, Lower, Upper, Steps, K, Brightness and OutputMode.
SpectralSetup spectral_setup(const ReferenceContext& c);

// k (the user's, or 1 / Σ ȳ over the sampled wavelengths) times the brightness: what sums of
// weight · cmf over Lower..Upper in Steps are multiplied by.
inline double output_scale(const SpectralSetup& s) {
    double ybar = 0;
    for (int nm = s.lower; nm <= s.upper; nm += s.steps) ybar += spectral::cmf_value(*s.cmf, s.observer, nm)[1] * s.cmf_unit;
    return (s.k > 0 ? s.k : 1.0 / ybar) * s.brightness;
}

// Eq. 9's largest absolute row sum: bounds how far any linear sRGB channel moves per unit of XYZ.
constexpr double kXyzToRgbRowSum = 3.240479 + 1.537150 + 0.498535;

// The exact sums' and ground truths' setting: every nm of 360-830 with the float CMFs and k = 1 / Σ ȳ,
// whatever the technique's Lower, Upper, Steps and ByteCmf (its brightness and gamut mapping kept).
SpectralSetup every_nm_setup(const ReferenceContext& c);

// Sum over the sampled wavelengths (every nm, or Lower..Upper in Steps) of weight(nm) * cmf(nm),
// times k (the user's, or 1 / sum ybar) and the brightness.
template <typename Weight>
spectral::Vec3 integrate(const SpectralSetup& s, bool every_nm, Weight weight) {
    spectral::Vec3 xyz{0, 0, 0};
    double ybar = 0;
    for (int nm = s.lower; nm <= s.upper; nm += every_nm ? 1 : s.steps) {
        const spectral::Vec3 cmf = spectral::cmf_value(*s.cmf, s.observer, nm);
        const double w = weight(nm);
        for (int c = 0; c < 3; ++c) xyz[c] += w * cmf[c] * s.cmf_unit;
        ybar += cmf[1] * s.cmf_unit;
    }
    const double k = (s.k > 0 ? s.k : 1.0 / ybar) * s.brightness;
    for (double& v : xyz) v *= k;
    return xyz;
}

// How far the linear sRGB output can move when the weight of each sampled wavelength is uncertain by
// uncertainty(nm): the uncertain weights' CMF contributions times k, through eq. 9 (its largest
// absolute row sum, 5.28, bounds any channel; clipping only shrinks the change).
template <typename Uncertainty>
double colour_uncertainty(const SpectralSetup& s, Uncertainty uncertainty) {
    double ybar = 0, spread = 0;
    for (int nm = s.lower; nm <= s.upper; nm += s.steps) {
        const spectral::Vec3 cmf = spectral::cmf_value(*s.cmf, s.observer, nm);
        ybar += cmf[1] * s.cmf_unit;
        spread += uncertainty(nm) * std::max({cmf[0], cmf[1], cmf[2]}) * s.cmf_unit;
    }
    return spread * kXyzToRgbRowSum * (s.k > 0 ? s.k : 1.0 / ybar) * s.brightness;
}

// How much larger than at Brightness = `reference_brightness` with automatic k the linear output is:
// absolute float errors grow with it, so absolute tolerances measured at the defaults scale by it.
double output_gain(const SpectralSetup& s, double reference_brightness);

// The effect's output for an XYZ value: linear sRGB after the gamut mapping `mode` (OutputMode), alpha 1.
std::array<double, 4> to_rgba(const spectral::Vec3& xyz, int mode);

}  // namespace fxview::reference
