#include "optics/fresnel.hpp"

namespace fxview::optics {

Complex refracted_cos(Complex n_i, Complex n_t, Complex cos_i) {
    const Complex ratio2 = (n_i / n_t) * (n_i / n_t);
    // 1 - ratio² (1 - cos_i²), summed so that equal indices give cos_t = cos_i even where 1 - cos_i²
    // rounds to 1 (cos_i below 1e-8).
    Complex cos_t = std::sqrt((1.0 - ratio2) + ratio2 * cos_i * cos_i);
    // The principal root already has Re ≥ 0; on the imaginary axis (total internal reflection in a
    // lossless medium) pick Im ≥ 0 so that exp(i k n d cos) decays.
    if (cos_t.real() == 0.0 && cos_t.imag() < 0.0) cos_t = -cos_t;
    return cos_t;
}

Amplitudes fresnel(Complex n_i, Complex n_t, Complex cos_i, Complex cos_t, Polarisation polarisation) {
    const Complex denominator = polarisation == Polarisation::S ? n_i * cos_i + n_t * cos_t : n_t * cos_i + n_i * cos_t;
    // Both terms vanish only at grazing incidence on equal indices: there is no interface, so r = 0
    // and t = 1 (the limit as n_t -> n_i), not 0/0.
    if (denominator == Complex(0.0)) return {0.0, 1.0};
    if (polarisation == Polarisation::S) return {(n_i * cos_i - n_t * cos_t) / denominator, 2.0 * n_i * cos_i / denominator};
    return {(n_t * cos_i - n_i * cos_t) / denominator, 2.0 * n_i * cos_i / denominator};
}

double interface_reflectance(Complex n_i, Complex n_t, double cos_i) {
    const Complex cos_t = refracted_cos(n_i, n_t, cos_i);
    return 0.5 * (std::norm(fresnel(n_i, n_t, cos_i, cos_t, Polarisation::S).r) +
                  std::norm(fresnel(n_i, n_t, cos_i, cos_t, Polarisation::P).r));
}

}  // namespace fxview::optics
