// What the references of analytic BRDFs share (brdf_reference, measured_reference): the world-space
// directions at a pixel, the radiance f · E · (n·l), and the per-pixel slack of a sharp highlight.
#pragma once
#include <algorithm>
#include <cmath>

#include "brdf/models.hpp"
#include "reference/reference.hpp"

namespace fxview::reference {

inline brdf::Directions directions(const ShadingInput& in) {
    brdf::Directions d;
    d.n = glm::normalize(in.normal);
    d.l = glm::normalize(in.light - in.position);
    d.v = glm::normalize(in.camera - in.position);
    // The tangent made orthogonal to n; any perpendicular where the mesh's tangent is parallel to n.
    glm::dvec3 t = in.tangent - d.n * glm::dot(d.n, in.tangent);
    if (glm::dot(t, t) < 1e-12) t = glm::cross(d.n, std::abs(d.n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
    d.t = glm::normalize(t);
    return d;
}

template <typename Model>
glm::dvec3 radiance(const Model& model, const brdf::Directions& d, double irradiance) {
    return brdf::evaluate(model, d) * irradiance * std::max(glm::dot(d.n, d.l), 0.0);
}

// The GPU's cosines are float: n·h near 1 is only known to a few ulps (~2.4e-7 absolute), which near
// a highlight's peak is an angle of sqrt(2 · 2.4e-7) = 7e-4 rad, far from the peak about 2.4e-7 /
// sin θh. The slack is how much the radiance changes when the normal tilts by that angle (either way,
// about two axes): large only where the lobe is steep, in sharp highlights.
constexpr double kCosineUlps = 2.4e-7;

// The largest change of value(d) (RGB) when the normal tilts by the float uncertainty of n·h (above),
// either way about two axes.
template <typename Value>
double tilt_spread(const Value& value, const brdf::Directions& d) {
    const glm::dvec3 h = glm::normalize(d.l + d.v);
    const double cos_h = std::clamp(glm::dot(d.n, h), 0.0, 1.0), sin_h = std::sqrt(1.0 - cos_h * cos_h);
    // The tilt δ that moves n·h by kCosineUlps: cos·δ²/2 + sin·δ = ε.
    const double tilt = cos_h > 0 ? std::max((-sin_h + std::sqrt(sin_h * sin_h + 2.0 * cos_h * kCosineUlps)) / cos_h, 4e-7) : 4e-7;
    glm::dvec3 axis = glm::cross(d.n, h);
    axis = glm::dot(axis, axis) > 1e-20 ? glm::normalize(axis) : d.t;
    const glm::dvec3 centre = value(d);
    double spread = 0;
    for (const glm::dvec3& towards : {axis, glm::cross(d.n, axis)})
        for (const double sign : {-1.0, 1.0}) {
            brdf::Directions tilted = d;
            tilted.n = glm::normalize(d.n + sign * tilt * towards);
            const glm::dvec3 change = glm::abs(value(tilted) - centre);
            spread = std::max({spread, change.r, change.g, change.b});
        }
    return spread;
}

template <typename Model>
double tilt_sensitivity(const Model& model, const brdf::Directions& d, double irradiance) {
    return tilt_spread([&](const brdf::Directions& at) { return radiance(model, at, irradiance); }, d);
}

}  // namespace fxview::reference
