#include "optics/thin_film.hpp"

#include <array>
#include <numbers>

namespace fxview::optics {
namespace {

using Matrix = std::array<Complex, 4>;  // row-major 2x2

Matrix multiply(const Matrix& a, const Matrix& b) {
    return {a[0] * b[0] + a[1] * b[2], a[0] * b[1] + a[1] * b[3], a[2] * b[0] + a[3] * b[2], a[2] * b[1] + a[3] * b[3]};
}

Complex admittance(Complex index, Complex cos_theta, Polarisation polarisation) {
    return polarisation == Polarisation::S ? index * cos_theta : index / cos_theta;
}

double phase_factor(double wavelength_nm) { return 2.0 * std::numbers::pi / wavelength_nm; }

}  // namespace

Response transfer_matrix(const Stack& stack, double wavelength_nm, double cos_outer, Polarisation polarisation) {
    // Grazing incidence reflects everything (r -> -1 in both polarisations) as soon as the stack has
    // any interface; an index-matched stack has none and transmits everything. The p admittance
    // n / cos would divide by zero there.
    if (cos_outer <= 0.0) {
        bool matched = stack.substrate == Complex(stack.outer);
        for (const Layer& layer : stack.layers) matched = matched && layer.index == Complex(stack.outer);
        return matched ? Response{0.0, 1.0} : Response{1.0, 0.0};
    }
    const Complex eta0 = admittance(stack.outer, cos_outer, polarisation);
    Matrix product{1.0, 0.0, 0.0, 1.0};
    for (const Layer& layer : stack.layers) {
        const Complex cos_j = refracted_cos(stack.outer, layer.index, cos_outer);
        const Complex eta = admittance(layer.index, cos_j, polarisation);
        // With n̂ = n + iκ and fields ~ exp(i(kz − ωt)) a layer's phase thickness has Im δ ≥ 0 and the
        // matrix carries −i (Born & Wolf's sign); Macleod's +i belongs to n − iκ.
        const Complex delta = phase_factor(wavelength_nm) * layer.index * layer.thickness_nm * cos_j;
        const Complex c = std::cos(delta), s = std::sin(delta);
        const Complex minus_i(0.0, -1.0);
        product = multiply(product, {c, minus_i * s / eta, minus_i * eta * s, c});
    }
    const Complex eta_sub = admittance(stack.substrate, refracted_cos(stack.outer, stack.substrate, cos_outer), polarisation);
    const Complex b = product[0] + product[1] * eta_sub, c = product[2] + product[3] * eta_sub;
    const Complex denominator = eta0 * b + c;
    Response response;
    response.reflectance = std::norm((eta0 * b - c) / denominator);
    response.transmittance = 4.0 * eta0.real() * eta_sub.real() / std::norm(denominator);
    return response;
}

double transfer_matrix_reflectance(const Stack& stack, double wavelength_nm, double cos_outer) {
    return 0.5 * (transfer_matrix(stack, wavelength_nm, cos_outer, Polarisation::S).reflectance +
                  transfer_matrix(stack, wavelength_nm, cos_outer, Polarisation::P).reflectance);
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
