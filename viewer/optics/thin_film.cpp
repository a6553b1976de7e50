#include "optics/thin_film.hpp"
#include "optics/prepared_stack.hpp"

#include <numbers>

namespace fxview::optics {
namespace {

double phase_factor(double wavelength_nm) { return 2.0 * std::numbers::pi / wavelength_nm; }

}  // namespace

Response transfer_matrix(const Stack& stack, double wavelength_nm, double cos_outer, Polarisation polarisation) {
    return PreparedStack(stack, cos_outer).response(wavelength_nm, polarisation);
}

double transfer_matrix_reflectance(const Stack& stack, double wavelength_nm, double cos_outer) {
    const auto [s, p] = PreparedStack(stack, cos_outer).reflectances(wavelength_nm);
    return 0.5 * (s + p);
}

double airy_reflectance(double n0, double n1, double n2, double thickness_nm, double wavelength_nm, double cos0,
                        Polarisation polarisation) {
    const Complex cos1 = refracted_cos(n0, n1, cos0), cos2 = refracted_cos(n0, n2, cos0);
    const double r01 = fresnel(n0, n1, cos0, cos1, polarisation).r.real();
    const double r12 = fresnel(n1, n2, cos1, cos2, polarisation).r.real();
    const double cos_delta = std::cos(2.0 * phase_factor(wavelength_nm) * n1 * thickness_nm * cos1.real());
    return (r01 * r01 + r12 * r12 + 2.0 * r01 * r12 * cos_delta) / (1.0 + r01 * r01 * r12 * r12 + 2.0 * r01 * r12 * cos_delta);
}

double airy_reflectance(double n0, double n1, double n2, double thickness_nm, double wavelength_nm, double cos0) {
    return 0.5 * (airy_reflectance(n0, n1, n2, thickness_nm, wavelength_nm, cos0, Polarisation::S) +
                  airy_reflectance(n0, n1, n2, thickness_nm, wavelength_nm, cos0, Polarisation::P));
}

double bubble_reflectance(double n_outer, double n_film, double thickness_nm, double wavelength_nm, double cos0) {
    const Complex cos1 = refracted_cos(n_outer, n_film, cos0);
    const double cos_delta = std::cos(2.0 * phase_factor(wavelength_nm) * n_film * thickness_nm * cos1.real());
    double sum = 0;
    for (const Polarisation polarisation : {Polarisation::S, Polarisation::P}) {
        const double r2 = std::norm(fresnel(n_outer, n_film, cos0, cos1, polarisation).r);
        sum += 2.0 * r2 * (1.0 - cos_delta) / (1.0 + r2 * r2 - 2.0 * r2 * cos_delta);
    }
    return 0.5 * sum;
}

}  // namespace fxview::optics
