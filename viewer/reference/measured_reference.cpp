#include "reference/measured_reference.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "brdf/models.hpp"
#include "reference/area_light_brdf.hpp"
#include "reference/brdf_sensitivity.hpp"

namespace fxview::reference {
namespace {

constexpr double kPi = std::numbers::pi;

struct Geometry {
    brdf::Directions d;
    double nl, nv;
    glm::dvec3 angles;       // φo, θo, θi in radians, as the grid counts them
    glm::dvec3 angle_error;  // how far float rounding can move each on the GPU
};

Geometry geometry(const brdf::Directions& d) {
    Geometry g;
    g.d = d;
    g.nl = glm::dot(g.d.n, g.d.l);
    g.nv = glm::dot(g.d.n, g.d.v);
    const glm::dvec3 lp = g.d.l - g.d.n * g.nl, vp = g.d.v - g.d.n * g.nv;
    const bool azimuth = glm::dot(lp, lp) > 1e-12 && glm::dot(vp, vp) > 1e-12;
    const double phi = azimuth ? kPi - std::acos(std::clamp(glm::dot(glm::normalize(lp), glm::normalize(vp)), -1.0, 1.0)) : 0.0;
    g.angles = {phi, std::acos(std::clamp(g.nv, -1.0, 1.0)), std::acos(std::clamp(g.nl, -1.0, 1.0))};
    // A float cosine is known to a few ulps (2.4e-7): acos turns that into up to sqrt(2 · 2.4e-7) =
    // 7e-4 rad near 0°, about 2.4e-7 / sin θ elsewhere; the azimuth of a short projection (a direction
    // near the normal) is known to about 2.4e-7 / its length.
    const auto acos_error = [](double theta) { return std::min(std::sqrt(2 * kCosineUlps), kCosineUlps / std::max(std::sin(theta), 1e-12)); };
    const double shortest = std::sqrt(std::min(glm::dot(lp, lp), glm::dot(vp, vp)));
    g.angle_error = {azimuth ? std::min(kPi, acos_error(g.angles.x) + kCosineUlps / std::max(shortest, 1e-12)) : 0.0,
                     acos_error(g.angles.y), acos_error(g.angles.z)};
    return g;
}

// The table at the given angles: texel centres sit at the grid's samples, so 0..1 over the grid maps
// onto the first..last centre.
glm::dvec3 measured(const ReferenceContext& c, const glm::dvec3& angles, double* footprint_spread = nullptr) {
    const glm::dvec3 unit = angles / glm::dvec3(kPi, kPi / 2, kPi / 2);
    const glm::dvec3 size(c.texture_size("Measured"));
    return glm::dvec3(c.sample_3d("Measured", (unit * (size - 1.0) + 0.5) / size, footprint_spread));
}

brdf::AshikhminShirleyFit fit_model(const ReferenceContext& c) {
    const auto colour = [&](const std::string& name) {
        const auto& v = c.values.numbers.at(name);
        return glm::dvec3(v.at(0), v.at(1), v.at(2));
    };
    return {colour("FitDiffuse"), colour("FitSpecular"), c.number("FitExponent")};
}

enum class Show { Measured, Fitted, Difference };

glm::dvec3 brdf_value(Show show, const ReferenceContext& c, const Geometry& g, const glm::dvec3& angles, double* footprint_spread = nullptr) {
    if (g.nl <= 0 || g.nv <= 0) return glm::dvec3(0.0);
    switch (show) {
        case Show::Measured: return measured(c, angles, footprint_spread);
        case Show::Fitted: return brdf::evaluate(fit_model(c), g.d);
        case Show::Difference: return c.number("DifferenceScale") * glm::abs(measured(c, angles, footprint_spread) - brdf::evaluate(fit_model(c), g.d));
    }
    return glm::dvec3(0.0);
}

// GPUs filter with a few fractional bits in the weights (8 in Direct3D's rules, which GL hardware
// follows; GL leaves it open): the result may be off by the footprint's spread over 2^8.
constexpr double kWeightResolution = 1.0 / 256.0;

// How far the table's value at g may move on the GPU: the angles' float uncertainty (one angle at a
// time) and the filter weights' resolution.
double table_spread(Show show, const ReferenceContext& c, const Geometry& g) {
    double footprint = 0;
    const glm::dvec3 centre = brdf_value(show, c, g, g.angles, &footprint);
    double spread = 0;
    for (int a = 0; a < 3; ++a)
        for (const double sign : {-1.0, 1.0}) {
            glm::dvec3 moved = g.angles;
            moved[a] = std::max(moved[a] + sign * g.angle_error[a], 0.0);
            const glm::dvec3 change = glm::abs(brdf_value(show, c, g, moved) - centre);
            spread = std::max({spread, change.r, change.g, change.b});
        }
    const double scale = show == Show::Difference ? c.number("DifferenceScale") : 1.0;
    return spread + scale * footprint * kWeightResolution;
}

// The GGX width the sized light's lobe directions are drawn with: the fitted exponent's lobe.
double lobe_alpha(const ReferenceContext& c) { return std::sqrt(2.0 / (c.number("FitExponent") + 2.0)); }

// The value f towards any l for the pixel's eye and frame, and a bound of what float may move it by.
BrdfTowards towards(Show show, const ReferenceContext& c, const brdf::Directions& d) {
    return [show, &c, d](const glm::dvec3& l) {
        brdf::Directions at = d;
        at.l = l;
        const Geometry g = geometry(at);
        return brdf_value(show, c, g, g.angles);
    };
}
BrdfTowards spread_towards(Show show, const ReferenceContext& c, const brdf::Directions& d) {
    return [show, &c, d](const glm::dvec3& l) {
        brdf::Directions at = d;
        at.l = l;
        const Geometry g = geometry(at);
        double slack = table_spread(show, c, g);
        if (show != Show::Measured) slack += tilt_spread([&](const brdf::Directions& tilted) { return brdf::evaluate(fit_model(c), tilted); }, at);
        return glm::dvec3(g.nl > 0 && g.nv > 0 ? slack : 0.0);
    };
}

Reference make(Show show) {
    Reference r;
    r.shade = [show](const ShadingInput& in, const ReferenceContext& c) {
        const Geometry g = geometry(directions(in));
        const glm::dvec3 l = light_is_sized(in) ? c.number("LightIrradiance") * area_light_brdf(in, g.d, towards(show, c, g.d), lobe_alpha(c))
                                                : brdf_value(show, c, g, g.angles) * c.number("LightIrradiance") * std::max(g.nl, 0.0);
        return std::array<double, 4>{l.r, l.g, l.b, 1.0};
    };
    // The table: where it is steep, the angles' float uncertainty moves the lookup (one angle at a
    // time), and the filter weights' resolution moves the blend. The model: a sharp highlight's slack.
    // Under a sized light the same bounds summed with the light's weights (the sum is linear in f),
    // plus the lobe directions within float's reach of its outline.
    r.slack = [show](const ShadingInput& in, const ReferenceContext& c) {
        const Geometry g = geometry(directions(in));
        if (light_is_sized(in)) {
            double edge = 0;
            area_light_brdf(in, g.d, towards(show, c, g.d), lobe_alpha(c), &edge);
            const glm::dvec3 spread = area_light_brdf(in, g.d, spread_towards(show, c, g.d), lobe_alpha(c));
            const glm::dvec3 value = glm::abs(area_light_brdf(in, g.d, towards(show, c, g.d), lobe_alpha(c)));
            return c.number("LightIrradiance") * (edge + spread.r + std::max({value.r, value.g, value.b}) * near_light_rounding(in));
        }
        const double irradiance = c.number("LightIrradiance") * std::max(g.nl, 0.0);
        const double slack = show == Show::Measured ? 0.0 : tilt_sensitivity(fit_model(c), g.d, c.number("LightIrradiance"));
        if (show == Show::Fitted) return slack;
        return slack + table_spread(show, c, g) * irradiance;
    };
    r.truth = [show](const ShadingInput& in, const ReferenceContext& c, unsigned) {
        const Geometry g = geometry(directions(in));
        const glm::dvec3 l = light_is_sized(in) ? c.number("LightIrradiance") * area_light_brdf_integral(in, g.d, towards(show, c, g.d), lobe_alpha(c))
                                                : brdf_value(show, c, g, g.angles) * c.number("LightIrradiance") * std::max(g.nl, 0.0);
        return std::array<double, 4>{l.r, l.g, l.b, 1.0};
    };
    r.truth_method = "the integral over the light (midpoint rules over its surface and about the mirror direction)";
    r.truth_with_sized_light = true;
    r.truth_deterministic_without_environment = true;
    r.tolerance = 1e-4;
    r.why = "float32 against double on radiances of order 1 (a few ulps of the cosines and of pow in the model); "
            "the table lookup adds per pixel what the angles' float uncertainty (up to 7e-4 rad near the normal, "
            "through acos) and 8-bit filter weights can move it";
    return r;
}

}  // namespace

std::map<std::string, Reference> measured_references() {
    std::map<std::string, Reference> all;
    all.emplace("Measured", make(Show::Measured));
    all.emplace("Fitted", make(Show::Fitted));
    all.emplace("Difference", make(Show::Difference));
    return all;
}

}  // namespace fxview::reference
