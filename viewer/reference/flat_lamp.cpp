#include "reference/flat_lamp.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fxview::reference {
namespace {

constexpr double kPi = std::numbers::pi;

// One element of the light at `point` of area `area`: its contributions to the three factors.
glm::dvec3 element(const scene::LightGeometry& light, const glm::dvec3& point, double area, const glm::dvec3& position, const glm::dvec3& n,
                   const glm::dvec3& v, double power, bool lobes, double rounding) {
    const glm::dvec3 d = point - position;
    const double r2 = glm::dot(d, d);
    const glm::dvec3 dir = d / std::sqrt(r2);
    const double emitted = -glm::dot(dir, light.normal), cosine = glm::dot(n, dir);
    if (emitted <= 0 || cosine <= 0) return glm::dvec3(0.0);
    const double w = light.radiance * area * emitted / r2;  // radiance x solid angle
    glm::dvec3 f(w * cosine, 0.0, 0.0);
    if (lobes) {
        const glm::dvec3 mirror = 2.0 * cosine * n - dir;
        f.y = w * std::pow(std::max(glm::dot(mirror, v), 0.0) * (1.0 + rounding), power);
        f.z = w * std::pow(std::max(glm::dot(n, glm::normalize(dir + v)), 0.0) * (1.0 + rounding), power);
    }
    return f;
}

}  // namespace

LampFactors flat_lamp_factors(const scene::LightGeometry& light, const glm::dvec3& position, const glm::dvec3& n, const glm::dvec3& v,
                              double power, bool lobes, double rounding) {
    const glm::dvec3 to_centre = light.centre - position;
    const double distance2 = std::max(glm::dot(to_centre, to_centre), 1e-12);
    const glm::dvec3 l = to_centre / std::sqrt(distance2);
    const double solid = std::min(light.area() * std::max(-glm::dot(l, light.normal), 0.0) / distance2, 2.0 * kPi);
    const double cos_theta = glm::dot(n, l);
    // The GPU's float may land on either side of a step of the count: `rounding` moves it as far (10 ulps).
    const double wanted = std::ceil(4.0 * solid * (lobes ? power : 1.0) * (1.0 + 10.0 * rounding));
    const double fewest = cos_theta * cos_theta * (1.0 + 10.0 * rounding) < solid / kPi ? 144.0 : 34.0;
    const int count = scene::flat_light_point_count(wanted, fewest);
    glm::dvec3 sum(0.0);
    for (int j = 0; j < count; ++j)
        sum += element(light, scene::flat_light_point(light, j, count), light.area() / count, position, n, v, power, lobes, rounding);
    return {sum.x, sum.y, sum.z};
}

LampFactors flat_lamp_integral(const scene::LightGeometry& light, const glm::dvec3& position, const glm::dvec3& n, const glm::dvec3& v,
                               double power) {
    glm::dvec3 sum(0.0);
    if (light.shape == scene::LightShape::Disc) {
        constexpr int kRings = 96, kAzimuths = 192;
        const double dr = light.radius / kRings;
        for (int i = 0; i < kRings; ++i) {
            const double r = (i + 0.5) * dr, area = r * dr * (2.0 * kPi / kAzimuths);
            for (int k = 0; k < kAzimuths; ++k) {
                const double phi = 2.0 * kPi * (k + 0.5) / kAzimuths;
                sum += element(light, light.centre + r * (std::cos(phi) * light.u + std::sin(phi) * light.v), area, position, n, v, power, true, 0.0);
            }
        }
    } else {
        constexpr int kCells = 160;
        const double area = light.area() / (kCells * kCells);
        for (int i = 0; i < kCells; ++i)
            for (int k = 0; k < kCells; ++k) {
                const glm::dvec2 q = light.half_size * (2.0 * glm::dvec2((i + 0.5) / kCells, (k + 0.5) / kCells) - 1.0);
                sum += element(light, light.centre + q.x * light.u + q.y * light.v, area, position, n, v, power, true, 0.0);
            }
    }
    return {sum.x, sum.y, sum.z};
}

}  // namespace fxview::reference
