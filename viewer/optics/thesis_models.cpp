#include "optics/thesis_models.hpp"

#include <cmath>
#include <numbers>

#include "optics/fresnel.hpp"

namespace fxview::optics::thesis {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct Angles {
    double cos0, cos1, cos2;
};

Angles angles(double n0, double n1, double n2, double cos0) {
    return {cos0, refracted_cos(n0, n1, cos0).real(), refracted_cos(n0, n2, cos0).real()};
}

// Code 14 with its argument order: the coefficient for light in `n_i` at cos_i meeting `n_t`.
double coefficient(double n_i, double n_t, double cos_i, double cos_t, Polarisation polarisation) {
    return fresnel(n_i, n_t, cos_i, cos_t, polarisation).r.real();
}

}  // namespace

PathDifference path_difference(double n0, double n1, double thickness_nm, double wavelength_nm, double cos_light,
                               double cos_view) {
    const double cos_alpha = refracted_cos(n0, n1, cos_light).real();
    const double cos_eye = cos_view * 0.1 + 0.9;
    const double cycles = 2.0 * thickness_nm * n1 * cos_alpha * cos_eye / wavelength_nm;
    return {cycles - std::floor(cycles), cycles};
}

double durikovic(double n0, double n1, double n2, double thickness_nm, double wavelength_nm, double cos0) {
    const Angles a = angles(n0, n1, n2, cos0);
    if (a.cos1 <= 0.0) return 1.0;
    const double cos_gamma = std::cos(kTwoPi / wavelength_nm * 2.0 * n1 * thickness_nm * a.cos1);
    double sum = 0;
    for (const Polarisation polarisation : {Polarisation::S, Polarisation::P}) {
        const double r10 = coefficient(n1, n0, a.cos1, a.cos0, polarisation);
        const double r12 = coefficient(n1, n2, a.cos1, a.cos2, polarisation);
        const double amplitude = (r10 + r12 * cos_gamma) / (1.0 + r12 * r10 * cos_gamma);
        sum += amplitude * amplitude;
    }
    return 0.5 * sum;
}

double alternative(double n0, double n1, double n2, double thickness_nm, double wavelength_nm, double cos0) {
    const Angles a = angles(n0, n1, n2, cos0);
    // Eq. 64: path in the film minus path in the outer medium; by Snell this is 2 n1 d cosθ1.
    const double sin0 = std::sqrt(std::max(0.0, 1.0 - a.cos0 * a.cos0));
    const double tan1 = std::sqrt(std::max(0.0, 1.0 - a.cos1 * a.cos1)) / a.cos1;
    if (a.cos1 <= 0.0) return 1.0;
    const double delta = kTwoPi / wavelength_nm * (2.0 * thickness_nm * n1 / a.cos1 - 2.0 * thickness_nm * n0 * tan1 * sin0);
    double sum = 0;
    for (const Polarisation polarisation : {Polarisation::S, Polarisation::P}) {
        const double r01 = coefficient(n0, n1, a.cos0, a.cos1, polarisation);
        const double r10 = coefficient(n1, n0, a.cos1, a.cos0, polarisation);
        const double r12 = coefficient(n1, n2, a.cos1, a.cos2, polarisation);
        const double t01 = std::abs(1.0 - r01), t10 = std::abs(1.0 - r10);
        const double trt = t01 * r12 * t10, trrrt = t01 * r12 * r10 * r12 * t10;
        const double sine = trt * std::sin(delta) + trrrt * std::sin(2.0 * delta);
        const double cosine = r01 * std::cos(delta) + trrrt * std::cos(2.0 * delta);
        sum += sine * sine + cosine * cosine;
    }
    // The truncated sum can exceed 1 (1.18 at n 2.5 / 3.0 / 1.0, 87°): never more light than arrives.
    return std::min(0.5 * sum, 1.0);
}

double fabry_perot(double n0, double n1, double thickness_nm, double wavelength_nm, double cos0) {
    const double cos1 = refracted_cos(n0, n1, cos0).real();
    if (cos1 <= 0.0) return 1.0;
    const double r = 0.5 * (std::abs(coefficient(n0, n1, cos0, cos1, Polarisation::P)) +
                            std::abs(coefficient(n0, n1, cos0, cos1, Polarisation::S)));
    const double half_delta = 0.5 * kTwoPi / wavelength_nm * 2.0 * n1 * thickness_nm * cos1;
    const double s = std::sin(half_delta);
    // 1 - 1/(1 + F s²), F = 4R/(1 - R)², written without F: at grazing incidence R = 1 and F is
    // infinite; a film of no thickness (s = 0) reflects nothing there (the limit along d = 0).
    const double numerator = 4.0 * r * s * s, denominator = (1.0 - r) * (1.0 - r) + numerator;
    return denominator > 0.0 ? numerator / denominator : 0.0;
}

}  // namespace fxview::optics::thesis
