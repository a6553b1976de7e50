// The Fourier transform of a sensitivity (a colour-matching function times a light) over 1/λ:
//     F_c(D) = Σ_λ S_c(λ) e^{i 2π D / λ},  S_c = cmf_c · light / Σ ȳ · light,
// at 1 nm steps over the integration range, D an optical path difference in nm. The spectral
// integral of anything of the form cos(2π D/λ + φ) against S is then one value of F: what lets a
// thin film's colour be a few look-ups instead of a 471-wavelength loop (optics/film_series.hpp).
// With the normalisation a perfect reflector has Y = 1 (F_Y(0) = 1).
#pragma once
#include <array>
#include <complex>
#include <vector>

#include "spectral/colorimetry.hpp"
#include "spectral/spectrum.hpp"

namespace fxview::spectral {

using ComplexXyz = std::array<std::complex<double>, 3>;

class SensitivityTransform {
public:
    SensitivityTransform(const Observer& observer, const Spectrum& light, const Integration& range = {});
    ComplexXyz at(double path_difference_nm) const;  // by the sum itself (exact)
    const Vec3& white() const { return white_; }     // F(0): the light's XYZ, Y = 1

private:
    Vec3 white_{};
    std::vector<double> inverse_wavelength_;
    std::vector<Vec3> weight_;
};

}  // namespace fxview::spectral
