#include "optics/grating.hpp"

#include <cmath>
#include <complex>
#include <numbers>

namespace fxview::optics {

double grating_intensity(double x, int tracks) {
    const double a = std::numbers::pi * x;
    const double denominator = tracks * std::sin(a);
    if (std::abs(denominator) < 1e-12) return 1.0;  // at an order: the limit of the quotient
    const double ratio = std::sin(tracks * a) / denominator;
    return ratio * ratio;
}

double grating_intensity_phasors(double x, int tracks) {
    std::complex<double> sum = 0.0;
    for (int k = 0; k < tracks; ++k) sum += std::polar(1.0, 2.0 * std::numbers::pi * k * x);
    return std::norm(sum) / (static_cast<double>(tracks) * tracks);
}

namespace thesis {

CdIntensity cd_intensity(double spacing_nm, double influence, double cos_view, double cos_light, double wavelength_nm,
                         double threshold) {
    CdIntensity result{};
    result.spacing_nm = spacing_nm * (1.0 + 2.0 * influence);
    result.cycles = result.spacing_nm * std::abs(cos_view - cos_light) / wavelength_nm;
    const double fraction = result.cycles - std::floor(result.cycles);
    result.intensity = fraction > threshold ? fraction : 0.0;
    return result;
}

}  // namespace thesis
}  // namespace fxview::optics
