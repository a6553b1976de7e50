#include "brdf/microfacet.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fxview::brdf {

double ggx_distribution(double n_dot_h, double alpha) {
    const double a2 = alpha * alpha;
    const double d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (std::numbers::pi * d * d);
}

double beckmann_distribution(double n_dot_h, double m, bool printed_form) {
    if (n_dot_h <= 0.0) return 0.0;
    const double cos2 = n_dot_h * n_dot_h;
    const double tan2 = (1.0 - cos2) / cos2;
    const double constant = printed_form ? 4.0 : std::numbers::pi;
    return std::exp(-tan2 / (m * m)) / (constant * m * m * cos2 * cos2);
}

double smith_schlick_ggx(double n_dot_v, double n_dot_l, double roughness) {
    const double k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
    const auto g1 = [k](double x) { return x / (x * (1.0 - k) + k); };
    return g1(n_dot_v) * g1(n_dot_l);
}

double v_cavity_geometry(double n_dot_h, double n_dot_v, double n_dot_l, double v_dot_h) {
    return std::min({1.0, 2.0 * n_dot_h * n_dot_v / v_dot_h, 2.0 * n_dot_h * n_dot_l / v_dot_h});
}

double fresnel_schlick(double f0, double cos_theta) { return f0 + (1.0 - f0) * std::pow(1.0 - cos_theta, 5.0); }

double fresnel_dielectric(double eta, double cos_theta) {
    const double c = cos_theta;
    const double g2 = eta * eta + c * c - 1.0;
    if (g2 < 0.0) return 1.0;
    const double g = std::sqrt(g2);
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

}  // namespace fxview::brdf
