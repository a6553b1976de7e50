#include "optics/grating_orders.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fxview::optics {
namespace {

double sinc_squared(double z) {
    if (z == 0) return 1.0;
    const double s = std::sin(std::numbers::pi * z) / (std::numbers::pi * z);
    return s * s;
}

}  // namespace

OrderRange propagating_orders(glm::dvec3 view, double wavelength_nm, double spacing_nm) {
    // |m λ/d − v_x| < √(1 − v_y²): m between (v_x ∓ √(1 − v_y²)) d/λ, exclusive.
    const double reach = std::sqrt(std::max(0.0, 1.0 - view.y * view.y)), scale = spacing_nm / wavelength_nm;
    OrderRange r;
    r.first = static_cast<int>(std::floor((view.x - reach) * scale)) + 1;
    r.last = static_cast<int>(std::ceil((view.x + reach) * scale)) - 1;
    if (r.first > 0) r.first = 0;  // the mirror order always propagates
    if (r.last < 0) r.last = 0;
    return r;
}

std::optional<glm::dvec3> order_incidence(glm::dvec3 view, int order, double wavelength_nm, double spacing_nm) {
    const double x = order * wavelength_nm / spacing_nm - view.x, y = -view.y, z2 = 1.0 - x * x - y * y;
    if (z2 <= 0) return std::nullopt;
    return glm::dvec3(x, y, std::sqrt(z2));
}

std::vector<double> order_efficiencies(const GratingOrderModel& model, OrderRange range) {
    std::vector<double> efficiencies(static_cast<size_t>(range.last - range.first + 1), 0.0);
    double weights = 0;  // Σ sinc²(m a) over the propagating m ≠ 0
    for (int m = range.first; m <= range.last; ++m)
        if (m != 0) weights += (efficiencies[static_cast<size_t>(m - range.first)] = sinc_squared(m * model.pit_fraction));
    for (int m = range.first; m <= range.last; ++m) {
        double& e = efficiencies[static_cast<size_t>(m - range.first)];
        if (m == 0) e = model.reflectance * (weights > 0 ? model.zero_order : 1.0);  // no other order: all in the mirror
        else e = model.reflectance * (1.0 - model.zero_order) * e / weights;
    }
    return efficiencies;
}

double light_edge_chord(double sin_alpha) {
    const double s = std::clamp(sin_alpha, 0.0, 1.0), c = std::sqrt(1.0 - s * s);
    return s * std::sqrt(2.0 / (1.0 + c));  // 2 sin(α/2) = √(2 (1 − cos α)), with 1 − cos α = s² / (1 + cos α)
}

double sphere_light_ramp_scale(double edge_chord, double width) {
    const double a = edge_chord - 0.5 * width, b = edge_chord + 0.5 * width;
    // ∫ p(c) (c − c³/2) dc: the full part up to a, then the ramp w ∫₀¹ (1 − t) f(a + t w) dt expanded
    // (no differences of nearly equal terms); from the centre, ∫₀ᵇ (b − c)/w (c − c³/2) dc.
    double moment = 0;
    if (a >= 0)
        moment = a * a / 2 - a * a * a * a / 8 +
                 width * (a / 2 + width / 6 - a * a * a / 4 - a * a * width / 4 - a * width * width / 8 - width * width * width / 40);
    else
        moment = (b * b * b / 6 - b * b * b * b * b / 40) / width;
    return moment > 0 ? 1.0 / (2.0 * std::numbers::pi * moment) : 0.0;
}

double sphere_light_radiance(double chord, double edge_chord, double width) {
    const double b = edge_chord + 0.5 * width;
    if (chord >= b) return 0.0;
    const double profile = width > 0 ? std::clamp((b - chord) / width, 0.0, 1.0) : (chord < edge_chord ? 1.0 : 0.0);
    return profile * sphere_light_ramp_scale(edge_chord, width);
}

}  // namespace fxview::optics
