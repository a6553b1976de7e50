#include "reference/area_light_brdf.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "brdf/microfacet.hpp"
#include "scene/light_geometry.hpp"

namespace fxview::reference {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kLobeSamples = 64;    // kFxLightLobeSamples
constexpr int kCosineSamples = 128;  // kFxLightCosineSamples

// Where a direction meets the light, float knows it to about this angle (a few ulps of the sampled
// direction's sines and cosines, 1e-6 each, and of the plane's intersection): lobe directions that
// close to the outline may fall on either side on the GPU, so their terms are slack.
constexpr double kEdgeAngle = 2e-5;

double radical_inverse(std::uint32_t i) {
    i = (i << 16u) | (i >> 16u);
    i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
    i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
    i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
    i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
    return i * 2.3283064365386963e-10;
}

double lobe_pdf(const brdf::Directions& d, const glm::dvec3& l, double alpha) {
    const glm::dvec3 h = glm::normalize(l + d.v);
    const double nh = glm::dot(d.n, h), vh = glm::dot(d.v, h);
    if (nh <= 0 || vh <= 0) return 0.0;
    return brdf::ggx_distribution(nh, alpha) * nh / (4.0 * vh);
}

// Direction i of the lobe's set: about the GGX normal at the Hammersley point of i.
glm::dvec3 lobe_direction(const brdf::Directions& d, int i, double alpha) {
    const double u1 = (i + 0.5) / kLobeSamples, u2 = radical_inverse(static_cast<std::uint32_t>(i));
    const double cos_theta = std::sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1)), sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    const glm::dvec3 x = d.t, y = glm::cross(d.n, d.t);
    const glm::dvec3 h = sin_theta * std::cos(2 * kPi * u2) * x + sin_theta * std::sin(2 * kPi * u2) * y + cos_theta * d.n;
    return 2.0 * glm::dot(d.v, h) * h - d.v;
}

// Direction i of the cosine-distributed set about n (Hammersley).
glm::dvec3 cosine_direction(const brdf::Directions& d, int i) {
    const double u1 = (i + 0.5) / kCosineSamples, u2 = radical_inverse(static_cast<std::uint32_t>(i)), r = std::sqrt(u1);
    const glm::dvec3 x = d.t, y = glm::cross(d.n, d.t);
    return r * std::cos(2 * kPi * u2) * x + r * std::sin(2 * kPi * u2) * y + std::sqrt(std::max(0.0, 1.0 - u1)) * d.n;
}

// The light as seen from the pixel, as the GPU's light_sampling() forms it.
struct Sampling {
    const scene::LightGeometry* lamp = nullptr;  // a flat light; null: a sphere
    glm::dvec3 position{0.0}, centre{0.0};
    double cos_alpha = 0, versine = 0, radiance = 0, density = 0, solid = 0;
    double nearness = 0;  // a flat light's area over the squared distance to its nearest point (capped at 2π); a sphere's Ω
};

Sampling sampling(const ShadingInput& in) {
    Sampling s;
    s.lamp = in.lamp.is_flat() ? &in.lamp : nullptr;
    s.position = in.position;
    const glm::dvec3 to_light = in.light - in.position;
    const double distance2 = std::max(glm::dot(to_light, to_light), 1e-12);
    s.centre = to_light / std::sqrt(distance2);
    if (s.lamp) {
        s.radiance = s.lamp->radiance;
        s.solid = std::min(s.lamp->area() * std::max(-glm::dot(s.centre, s.lamp->normal), 0.0) / distance2, 2 * kPi);
        const glm::dvec3 from_centre = in.position - s.lamp->centre;
        const glm::dvec2 below(glm::dot(from_centre, s.lamp->u), glm::dot(from_centre, s.lamp->v));
        const double outside = s.lamp->shape == scene::LightShape::Disc ? std::max(glm::length(below) - s.lamp->radius, 0.0)
                                                                          : glm::length(glm::max(glm::abs(below) - s.lamp->half_size, glm::dvec2(0.0)));
        const double height = glm::dot(from_centre, s.lamp->normal);
        s.nearness = std::min(s.lamp->area() / std::max(height * height + outside * outside, 1e-12), 2 * kPi);
    } else {
        const double sin2 = std::min(in.light_radius * in.light_radius / distance2, 0.9998);
        s.cos_alpha = std::sqrt(1.0 - sin2);
        s.versine = sin2 / (1.0 + s.cos_alpha);
        s.solid = 2 * kPi * s.versine;
        s.nearness = s.solid;
        s.radiance = 1.0 / (kPi * sin2);
        s.density = 1.0 / s.solid;
    }
    return s;
}

// Point j of `count` on the light as a unit direction, and its density per solid angle.
glm::dvec3 light_point(const Sampling& s, int j, int count, double& pdf) {
    if (s.lamp) {
        const glm::dvec3 d = scene::flat_light_point(*s.lamp, j, count) - s.position;
        const double r2 = glm::dot(d, d);
        const glm::dvec3 dir = d / std::sqrt(r2);
        const double emitted = -glm::dot(dir, s.lamp->normal);
        pdf = emitted > 0 ? r2 / (s.lamp->area() * emitted) : 0.0;
        return dir;
    }
    const glm::dvec3 l = s.centre;
    const double sgn = l.z >= 0 ? 1.0 : -1.0, a = -1.0 / (sgn + l.z), b = l.x * l.y * a;  // Duff et al.'s frame
    const glm::dvec3 x(1.0 + sgn * l.x * l.x * a, sgn * b, -sgn * l.x), y(b, sgn + l.y * l.y * a, -l.y);
    // Rings of equal solid angle with two opposite points each: cos θ sums exactly.
    const int ring = j / 2;
    const double c = 1.0 - (ring + 0.5) / (count / 2) * s.versine, sine = std::sqrt(std::max(1.0 - c * c, 0.0));
    const double phi = kPi * (3.0 - std::sqrt(5.0)) * ring + (j % 2 == 1 ? kPi : 0.0);
    pdf = s.density;
    return c * l + sine * (std::cos(phi) * x + std::sin(phi) * y);
}

// The light's density along unit `dir` (0: it misses), and how far (radians) the direction passes
// from the outline.
double light_pdf_along(const Sampling& s, const glm::dvec3& dir, double& margin) {
    if (!s.lamp) {
        const double cosine = glm::dot(dir, s.centre), sin_alpha = std::sqrt(std::max(1.0 - s.cos_alpha * s.cos_alpha, 1e-30));
        margin = std::abs(cosine - s.cos_alpha) / sin_alpha;
        return cosine >= s.cos_alpha ? s.density : 0.0;
    }
    const scene::LightGeometry& g = *s.lamp;
    const double towards = -glm::dot(dir, g.normal), height = glm::dot(s.position - g.centre, g.normal);
    margin = 1.0;
    if (towards <= 0 || height <= 0) return 0.0;
    const double t = height / towards;
    const glm::dvec3 q3 = s.position + t * dir - g.centre;
    const glm::dvec2 q(glm::dot(q3, g.u), glm::dot(q3, g.v));
    bool inside;
    if (g.shape == scene::LightShape::Disc) {
        inside = glm::length(q) <= g.radius;
        margin = std::abs(glm::length(q) - g.radius) / t;
    } else {
        inside = std::abs(q.x) <= g.half_size.x && std::abs(q.y) <= g.half_size.y;
        margin = std::min(std::abs(std::abs(q.x) - g.half_size.x), std::abs(std::abs(q.y) - g.half_size.y)) / t;
    }
    return inside ? t * t / (g.area() * towards) : 0.0;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The balance heuristic's sum with `count` light points, the lobe's and the cosine's directions
// counted by their shares; `edge` gathers the terms of directions within float's reach of the outline.
glm::dvec3 balance_sum(const Sampling& s, int count, const brdf::Directions& d, const BrdfTowards& f, double alpha, double& edge) {
    if (!s.lamp) count = count / 2 * 2;  // a sphere's points come in opposite pairs
    // The lobe's directions count by how many of them meet the light (all from 16, none below 4); the
    // cosine's where the light is near (`nearness` from 0.5 to 1.5).
    const double lights = count, hits = kLobeSamples * std::min(1.0, s.solid / (4.0 * kPi * alpha * alpha));
    const double lobes = kLobeSamples * std::clamp((hits - 4.0) / 12.0, 0.0, 1.0);
    const double cosines = kCosineSamples * std::clamp(s.nearness - 0.5, 0.0, 1.0);
    const auto denominator = [&](const glm::dvec3& l, double light_pdf) {
        return lights * light_pdf + lobes * lobe_pdf(d, l, alpha) + cosines * std::max(glm::dot(d.n, l), 0.0) / kPi;
    };
    glm::dvec3 sum(0.0);
    for (int j = 0; j < count; ++j) {
        double pdf = 0;
        const glm::dvec3 l = light_point(s, j, count, pdf);
        const double nl = glm::dot(d.n, l);
        if (nl <= 0 || !(pdf > 0)) continue;
        const glm::dvec3 value = f(l);
        if (!finite(value)) continue;
        sum += value * (nl * s.radiance / denominator(l, pdf));
    }
    // A set's direction that meets the light: its term times the set's share; one within float's reach
    // of the outline counts as slack (with the density it would have just inside).
    const auto direction_term = [&](const glm::dvec3& l, double share) {
        const double nl = glm::dot(d.n, l);
        double margin = 1.0;
        const double pdf = nl > 0 ? light_pdf_along(s, l, margin) : 0.0;
        const double near_pdf = margin < kEdgeAngle && pdf == 0.0 && nl > 0 ? (s.lamp ? 1.0 / std::max(s.solid, 1e-30) : s.density) : pdf;
        if (nl <= 0 || !(near_pdf > 0)) return;
        const glm::dvec3 value = f(l);
        if (!finite(value)) return;
        const glm::dvec3 term = share * value * (nl * s.radiance / denominator(l, near_pdf));
        if (pdf > 0) sum += term;
        if (margin < kEdgeAngle) edge += std::max({std::abs(term.r), std::abs(term.g), std::abs(term.b)});
    };
    for (int i = 0; i < kLobeSamples && lobes > 0; ++i) direction_term(lobe_direction(d, i, alpha), lobes / kLobeSamples);
    for (int i = 0; i < kCosineSamples && cosines > 0; ++i) direction_term(cosine_direction(d, i), cosines / kCosineSamples);
    return sum;
}

}  // namespace

bool light_is_sized(const ShadingInput& in) { return in.lamp.is_flat() || in.light_radius > 0.0; }

glm::dvec3 area_light_brdf(const ShadingInput& in, const brdf::Directions& d, const BrdfTowards& f, double alpha, double* edge_slack) {
    if (glm::dot(d.n, d.v) <= 0) return glm::dvec3(0.0);
    const Sampling s = sampling(in);
    alpha = std::clamp(alpha, 0.001, 1.0);
    // 89 points, 144 where the horizon crosses the light, 233 where the light is near (the shader's
    // light_sampling); float may decide either way where a test nearly flips: the other count's
    // difference is slack there.
    const double cos_theta = glm::dot(d.n, s.centre), horizon = cos_theta * cos_theta - s.solid / 3.14159265, near = s.nearness - 1.5;
    const auto count = [](double horizon_test, double near_test) { return near_test > 0 ? 233 : horizon_test < 0 ? 144 : 89; };
    double edge = 0;
    const glm::dvec3 sum = balance_sum(s, count(horizon, near), d, f, alpha, edge);
    if (edge_slack) {
        const bool horizon_close = std::abs(horizon) < 1e-6 + 1e-5 * s.solid, near_close = std::abs(near) < 1e-5 * 1.5;
        for (const int other : {horizon_close ? count(-horizon, near) : 0, near_close ? count(horizon, -near) : 0}) {
            if (other == 0 || other == count(horizon, near)) continue;
            double other_edge = 0;
            const glm::dvec3 change = glm::abs(balance_sum(s, other, d, f, alpha, other_edge) - sum);
            edge += std::max({change.r, change.g, change.b});
        }
        *edge_slack = edge;
    }
    return sum;
}

double near_light_rounding(const ShadingInput& in) {
    double nearest = glm::length(in.light - in.position) - std::max(in.light_radius, 0.0);
    if (in.lamp.is_flat()) {
        const glm::dvec3 from_centre = in.position - in.lamp.centre;
        const glm::dvec2 below(glm::dot(from_centre, in.lamp.u), glm::dot(from_centre, in.lamp.v));
        const double outside = in.lamp.shape == scene::LightShape::Disc ? std::max(glm::length(below) - in.lamp.radius, 0.0)
                                                                          : glm::length(glm::max(glm::abs(below) - in.lamp.half_size, glm::dvec2(0.0)));
        nearest = std::hypot(glm::dot(from_centre, in.lamp.normal), outside);
    }
    return 2.0 * 1.2e-7 / std::max(nearest, 1e-9);
}

glm::dvec3 area_light_brdf_integral(const ShadingInput& in, const brdf::Directions& d, const BrdfTowards& f, double alpha) {
    if (glm::dot(d.n, d.v) <= 0) return glm::dvec3(0.0);
    const Sampling s = sampling(in);
    // Two midpoint grids combined by the balance heuristic: the light's own surface (or disc of
    // directions) in elements of equal solid angle or equal area, and a cone about the mirror
    // direction, half-angle 8 α (at least 0.02 rad, at most the hemisphere), in elements of equal
    // solid angle: the light grid resolves the light, the cone grid a lobe sharper than its elements.
    constexpr int kConeRings = 128, kConeAzimuths = 256;
    const glm::dvec3 mirror = 2.0 * glm::dot(d.n, d.v) * d.n - d.v;
    const double cone_angle = std::clamp(8.0 * alpha, 0.02, kPi / 2), cone_cos = std::cos(cone_angle), cone_versine = 1.0 - cone_cos;
    const double cone_solid = 2 * kPi * cone_versine, cones = static_cast<double>(kConeRings) * kConeAzimuths;
    const int light_cells = !s.lamp ? 160 * 320 : s.lamp->shape == scene::LightShape::Disc ? 128 * 256 : 200 * 200;
    const auto light_density = [&](const glm::dvec3& dir) {  // per solid angle, the light grid's
        if (!s.lamp) return glm::dot(dir, s.centre) >= s.cos_alpha ? 1.0 / s.solid : 0.0;
        double margin = 0;
        return light_pdf_along(s, dir, margin);  // uniform in area: r² / (A cos)
    };
    const auto cone_density = [&](const glm::dvec3& dir) { return glm::dot(dir, mirror) >= cone_cos ? 1.0 / cone_solid : 0.0; };
    glm::dvec3 sum(0.0);
    const auto add = [&](const glm::dvec3& dir, double light_pdf, double cone_pdf) {
        const double nl = glm::dot(d.n, dir), denominator = light_cells * light_pdf + cones * cone_pdf;
        if (nl <= 0 || !(denominator > 0)) return;
        const glm::dvec3 value = f(dir);
        if (finite(value)) sum += value * (nl * s.radiance / denominator);
    };
    // The light grid.
    const auto add_element = [&](const glm::dvec3& point) {
        const glm::dvec3 to = point - s.position;
        const double r2 = glm::dot(to, to);
        const glm::dvec3 dir = to / std::sqrt(r2);
        const double emitted = -glm::dot(dir, s.lamp->normal);
        if (emitted > 0) add(dir, r2 / (s.lamp->area() * emitted), cone_density(dir));
    };
    if (!s.lamp) {
        constexpr int kRings = 160, kAzimuths = 320;
        const glm::dvec3 l = s.centre, x = glm::normalize(glm::cross(std::abs(l.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), l)), y = glm::cross(l, x);
        for (int k = 0; k < kRings; ++k) {
            const double c = 1.0 - (k + 0.5) / kRings * s.versine, sine = std::sqrt(std::max(1.0 - c * c, 0.0));
            for (int m = 0; m < kAzimuths; ++m) {
                const double phi = 2 * kPi * (m + 0.5) / kAzimuths;
                const glm::dvec3 dir = c * l + sine * (std::cos(phi) * x + std::sin(phi) * y);
                add(dir, 1.0 / s.solid, cone_density(dir));
            }
        }
    } else if (s.lamp->shape == scene::LightShape::Disc) {
        constexpr int kRings = 128, kAzimuths = 256;  // rings of equal area
        for (int k = 0; k < kRings; ++k) {
            const double r = s.lamp->radius * std::sqrt((k + 0.5) / kRings);
            for (int m = 0; m < kAzimuths; ++m) {
                const double phi = 2 * kPi * (m + 0.5) / kAzimuths;
                add_element(s.lamp->centre + r * (std::cos(phi) * s.lamp->u + std::sin(phi) * s.lamp->v));
            }
        }
    } else {
        constexpr int kCells = 200;
        for (int i = 0; i < kCells; ++i)
            for (int k = 0; k < kCells; ++k) {
                const glm::dvec2 q = s.lamp->half_size * (2.0 * glm::dvec2((i + 0.5) / kCells, (k + 0.5) / kCells) - 1.0);
                add_element(s.lamp->centre + q.x * s.lamp->u + q.y * s.lamp->v);
            }
    }
    // The cone grid: its directions that meet the light.
    const glm::dvec3 cx = glm::normalize(glm::cross(std::abs(mirror.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), mirror)), cy = glm::cross(mirror, cx);
    for (int k = 0; k < kConeRings; ++k) {
        const double c = 1.0 - (k + 0.5) / kConeRings * cone_versine, sine = std::sqrt(std::max(1.0 - c * c, 0.0));
        for (int m = 0; m < kConeAzimuths; ++m) {
            const double phi = 2 * kPi * (m + 0.5) / kConeAzimuths;
            const glm::dvec3 dir = c * mirror + sine * (std::cos(phi) * cx + std::sin(phi) * cy);
            const double light_pdf = light_density(dir);
            if (light_pdf > 0) add(dir, light_pdf, 1.0 / cone_solid);
        }
    }
    return sum;
}

}  // namespace fxview::reference
