#include "spectral/sensitivity_transform.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace fxview::spectral {

SensitivityTransform::SensitivityTransform(const Observer& observer, const Spectrum& light, const Integration& range) {
    double luminance = 0;
    for (int nm = range.lower; nm <= range.upper; nm += range.step) luminance += observer.y.at(nm) * light.at(nm);
    if (!(luminance > 0)) throw Error("sensitivity transform: the light has no luminance in the integration range");
    for (int nm = range.lower; nm <= range.upper; nm += range.step) {
        inverse_wavelength_.push_back(1.0 / nm);
        weight_.push_back({observer.x.at(nm) * light.at(nm) / luminance, observer.y.at(nm) * light.at(nm) / luminance,
                           observer.z.at(nm) * light.at(nm) / luminance});
        for (size_t c = 0; c < 3; ++c) white_[c] += weight_.back()[c];
    }
}

ComplexXyz SensitivityTransform::at(double path_difference_nm) const {
    ComplexXyz sum{};
    for (size_t i = 0; i < weight_.size(); ++i) {
        const std::complex<double> phase = std::polar(1.0, 2.0 * std::numbers::pi * path_difference_nm * inverse_wavelength_[i]);
        for (size_t c = 0; c < 3; ++c) sum[c] += weight_[i][c] * phase;
    }
    return sum;
}

}  // namespace fxview::spectral
