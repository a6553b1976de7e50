#include "scene/light_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "scene/scene.hpp"

namespace fxview::scene {
namespace {

constexpr double kPi = std::numbers::pi;

// Fibonacci numbers for the quadrature's counts and the lattice's step (the one before).
constexpr std::array<int, 6> kFibonacci = {21, 34, 55, 89, 144, 233};

// ∫ of the area inside the outline offset inwards by σ, σ from 0 to x, and outwards by d, d from 0 to
// y, for half extents (h1, h2): the layer-cake form of the ramp's integral (ellipse: π(h1 ∓ σ)(h2 ∓ σ);
// rectangle: 4(h1 − σ)(h2 − σ) inside, 4 h1 h2 + 4 d (h1 + h2) + π d² outside, its corners rounded).
double offset_area_integral(LightShape shape, glm::dvec2 h, double x, double y) {
    const double product = h.x * h.y, sum = h.x + h.y;
    if (shape == LightShape::Disc)
        return kPi * (product * x - sum * x * x / 2 + x * x * x / 3) + kPi * (product * y + sum * y * y / 2 + y * y * y / 3);
    return 4 * (product * x - sum * x * x / 2 + x * x * x / 3) + (4 * product * y + 2 * sum * y * y + kPi * y * y * y / 3);
}

}  // namespace

std::optional<LightShape> parse_light_shape(std::string_view name) {
    if (name == "sphere" || name == "point") return LightShape::Sphere;
    if (name == "disc" || name == "disk") return LightShape::Disc;
    if (name == "rectangle" || name == "rect") return LightShape::Rectangle;
    return std::nullopt;
}

const char* light_shape_name(LightShape shape) {
    switch (shape) {
        case LightShape::Disc: return "disc";
        case LightShape::Rectangle: return "rectangle";
        default: return "sphere";
    }
}

double LightGeometry::area() const { return shape == LightShape::Disc ? kPi * half_size.x * half_size.x : 4.0 * half_size.x * half_size.y; }

double LightGeometry::equivalent_radius() const { return shape == LightShape::Rectangle ? std::sqrt(area() / kPi) : radius; }

std::vector<glm::dvec3> LightGeometry::outline(int segments) const {
    std::vector<glm::dvec3> points;
    if (shape == LightShape::Rectangle) {
        for (const glm::dvec2 corner : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
            points.push_back(centre + corner.x * half_size.x * u + corner.y * half_size.y * v);
        return points;
    }
    for (int i = 0; i < segments; ++i) {
        const double phi = 2.0 * kPi * i / segments;
        points.push_back(centre + radius * (std::cos(phi) * u + std::sin(phi) * v));
    }
    return points;
}

double flat_light_irradiance_at_origin(LightShape shape, glm::dvec2 half_size, double distance) {
    const double d2 = distance * distance;
    if (shape == LightShape::Disc) return kPi * half_size.x * half_size.x / (half_size.x * half_size.x + d2);
    const double a = half_size.x, b = half_size.y, ra = std::sqrt(a * a + d2), rb = std::sqrt(b * b + d2);
    return 2.0 * (a / ra * std::atan(b / ra) + b / rb * std::atan(a / rb));
}

LightGeometry light_geometry(const Light& light) {
    LightGeometry g;
    g.shape = light.shape;
    g.centre = glm::dvec3(light.world_position());
    const double distance = glm::length(g.centre);
    g.normal = distance > 0 ? -g.centre / distance : glm::dvec3(0, -1, 0);
    const glm::dvec3 horizontal = glm::cross(glm::dvec3(0, 1, 0), g.normal);
    g.u = glm::length(horizontal) > 1e-9 ? glm::normalize(horizontal) : glm::dvec3(1, 0, 0);
    g.v = glm::cross(g.normal, g.u);
    if (light.shape == LightShape::Rectangle) {
        g.half_size = glm::dvec2(std::max(light.size.x, 0.0f), std::max(light.size.y, 0.0f)) * 0.5;
    } else {
        g.radius = std::max(light.radius, 0.0f);
        g.half_size = glm::dvec2(g.radius);
    }
    if (light.shape != LightShape::Sphere && g.half_size.x > 0 && g.half_size.y > 0) {
        // A light of under 1e-12 sr seen from the origin is a point: its radiance would pass float's
        // range on the GPU (and 0 x inf make the picture black).
        const double irradiance = flat_light_irradiance_at_origin(light.shape, g.half_size, distance);
        if (irradiance > 1e-12) g.radiance = 1.0 / irradiance;
    }
    return g;
}

std::optional<FlatLightHit> flat_light_hit(const LightGeometry& light, const glm::dvec3& position, const glm::dvec3& direction) {
    const double towards = -glm::dot(direction, light.normal);  // > 0: the ray meets the emitting side
    const double height = glm::dot(position - light.centre, light.normal);
    if (towards <= 0 || height <= 0) return std::nullopt;
    const double t = height / towards;
    const glm::dvec3 hit = position + t * direction - light.centre;
    const glm::dvec2 q(glm::dot(hit, light.u), glm::dot(hit, light.v));
    double inside = 0;
    glm::dvec2 across(1, 0);  // in-plane direction across the outline
    if (light.shape == LightShape::Disc) {
        const double r = glm::length(q);
        inside = light.half_size.x - r;
        if (r > 0) across = q / r;
    } else {
        const glm::dvec2 beyond = glm::abs(q) - light.half_size, sign(q.x < 0 ? -1.0 : 1.0, q.y < 0 ? -1.0 : 1.0);
        if (beyond.x > 0 && beyond.y > 0) {
            inside = -glm::length(beyond);
            across = glm::normalize(beyond) * sign;
        } else if (beyond.x > beyond.y) {
            inside = -beyond.x;
            across = glm::dvec2(sign.x, 0);
        } else {
            inside = -beyond.y;
            across = glm::dvec2(0, sign.y);
        }
    }
    // The angle to the outline's nearest point, as the chord between unit directions (the in-plane
    // distance over t would vanish for rays that graze the light's plane).
    const glm::dvec2 edge = q + inside * across;
    FlatLightHit result;
    result.inside_angle = (inside < 0 ? -1.0 : inside > 0 ? 1.0 : 0.0) *
                          glm::length(direction - glm::normalize(light.centre + edge.x * light.u + edge.y * light.v - position));
    result.angular_half_size = flat_light_angular_half_size(light, position);
    return result;
}

glm::dvec2 flat_light_angular_half_size(const LightGeometry& light, const glm::dvec3& position) {
    // Seen from `position` towards the centre: a disc's ellipse (R/D, R cos/D), a rectangle's sides foreshortened.
    const glm::dvec3 to_centre = light.centre - position;
    const double distance = glm::length(to_centre);
    const glm::dvec3 l = to_centre / distance;
    if (light.shape == LightShape::Disc) return glm::dvec2(light.radius, light.radius * std::max(-glm::dot(l, light.normal), 0.0)) / distance;
    return glm::dvec2(light.half_size.x * std::sqrt(std::max(1.0 - glm::dot(l, light.u) * glm::dot(l, light.u), 0.0)),
                      light.half_size.y * std::sqrt(std::max(1.0 - glm::dot(l, light.v) * glm::dot(l, light.v), 0.0))) /
           distance;
}

double flat_light_radiance(const LightGeometry& light, const glm::dvec3& position, const glm::dvec3& direction, double width) {
    const std::optional<FlatLightHit> hit = flat_light_hit(light, position, direction);
    if (!hit) return 0.0;
    if (!(width > 0)) return hit->inside_angle >= 0 ? light.radiance : 0.0;
    const double ramp = std::clamp(0.5 + hit->inside_angle / width, 0.0, 1.0);
    if (ramp <= 0) return 0.0;
    return ramp * flat_light_ramp_scale(light, hit->angular_half_size, width);
}

double flat_light_ramp_scale(const LightGeometry& light, glm::dvec2 h, double width) {
    const double sharp = light.shape == LightShape::Disc ? kPi * h.x * h.y : 4.0 * h.x * h.y;
    const double ramped = offset_area_integral(light.shape, h, std::min(0.5 * width, std::min(h.x, h.y)), 0.5 * width) / width;
    return ramped > 0 ? light.radiance * sharp / ramped : 0.0;
}

int flat_light_point_count(double wanted, double fewest) {
    const double target = std::max(wanted, fewest);
    for (size_t i = 1; i < kFibonacci.size(); ++i)
        if (kFibonacci[i] >= target) return kFibonacci[i];
    return kFibonacci.back();
}

glm::dvec3 flat_light_point(const LightGeometry& light, int j, int count) {
    glm::dvec2 q;
    if (light.shape == LightShape::Disc) {
        const double r = std::sqrt((j + 0.5) / count), phi = kPi * (3.0 - std::sqrt(5.0)) * j;
        q = light.half_size.x * r * glm::dvec2(std::cos(phi), std::sin(phi));
    } else {
        int step = kFibonacci.front();
        for (size_t i = 1; i < kFibonacci.size(); ++i)
            if (kFibonacci[i] == count) step = kFibonacci[i - 1];
        q = light.half_size * (2.0 * glm::dvec2((j + 0.5) / count, ((j * step) % count + 0.5) / count) - 1.0);
    }
    return light.centre + q.x * light.u + q.y * light.v;
}

}  // namespace fxview::scene
