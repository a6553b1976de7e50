// The template part of environment_reference.hpp: filtered importance sampling as environment_light.glsl
// does it, and the Monte Carlo ground truth.
#pragma once
#include <cmath>
#include <numbers>

#include "lighting/image_based_lighting.hpp"

namespace fxview::reference {

template <typename Brdf>
glm::dvec3 EnvironmentLookup::light(const brdf::Directions& facing, const Brdf& f, double alpha, double* seam) const {
    constexpr int kSamples = 32;
    const brdf::Directions d = environment_facing(facing);
    const glm::dvec3 x = d.t, y = glm::cross(d.n, d.t);
    glm::dvec3 sum(0.0);
    double spread = 0.0;
    for (int i = 0; i < kSamples; ++i) {
        const glm::dvec2 u = lighting::hammersley(static_cast<unsigned>(i / 2), kSamples / 2);
        glm::dvec3 l;
        if (i % 2 == 0) {
            const double r = std::sqrt(u.x), phi = 2 * std::numbers::pi * u.y;
            l = r * std::cos(phi) * x + r * std::sin(phi) * y + std::sqrt(std::max(0.0, 1.0 - u.x)) * d.n;
        } else {
            const glm::dvec3 hl = lighting::sample_ggx(u.x, u.y, alpha);
            const glm::dvec3 h = hl.x * x + hl.y * y + hl.z * d.n;
            l = 2.0 * glm::dot(d.v, h) * h - d.v;
        }
        const glm::dvec3 h = glm::normalize(l + d.v);
        const double nh = glm::dot(d.n, h), a2 = alpha * alpha, q = nh * nh * (a2 - 1.0) + 1.0;
        const double pdf = 0.5 * std::max(glm::dot(d.n, l), 0.0) / std::numbers::pi +
                           0.5 * a2 / (std::numbers::pi * q * q) * nh / (4.0 * std::max(glm::dot(d.v, h), 1e-6));
        const double nl = glm::dot(d.n, l);
        if (nl <= 0.0 || !(pdf > 0.0)) continue;
        const glm::dvec3 value = f(l);
        if (!std::isfinite(value.r) || !std::isfinite(value.g) || !std::isfinite(value.b)) continue;
        const double share = 1.0 / (kSamples * pdf);
        const double roughness = std::sqrt(std::clamp(std::sqrt(share / (4.0 * std::numbers::pi)), 0.0, 1.0));
        double seam_here = 0.0;
        const glm::dvec3 weight = value * nl / pdf / static_cast<double>(kSamples);
        sum += weight * radiance(l, roughness, &seam_here);
        spread += seam_here * std::max({weight.r, weight.g, weight.b});
    }
    if (seam) *seam = spread;
    return sum + discs_shaded(d, f, alpha);
}

template <typename Brdf>
glm::dvec3 EnvironmentLookup::integral(const brdf::Directions& facing, const Brdf& f, double alpha, int samples, unsigned seed) const {
    const brdf::Directions d = environment_facing(facing);  // the normal the techniques shade with
    const glm::dvec3 t = d.t, b = glm::cross(d.n, d.t);
    // A per-pixel turn of the point set (Cranley-Patterson), so that pixels do not share one pattern.
    const auto hash = [](unsigned x) {
        x ^= x >> 16;
        x *= 0x7feb352dU;
        x ^= x >> 15;
        x *= 0x846ca68bU;
        return (x ^ (x >> 16)) * 2.3283064365386963e-10;
    };
    const glm::dvec2 shift(hash(seed), hash(seed * 7919u + 1u));
    const auto pdf_cosine = [&](double nl) { return nl / std::numbers::pi; };
    const auto pdf_ggx = [&](const glm::dvec3& l) {
        const glm::dvec3 h = glm::normalize(l + d.v);
        return lighting::ggx_d(glm::dot(d.n, h), alpha) * glm::dot(d.n, h) / (4.0 * std::max(glm::dot(d.v, h), 1e-12));
    };
    glm::dvec3 sum(0.0);
    for (int i = 0; i < samples; ++i) {
        glm::dvec2 u = lighting::hammersley(static_cast<unsigned>(i / 2), static_cast<unsigned>(samples / 2)) + shift;
        u -= glm::floor(u);
        glm::dvec3 l;
        if (i % 2 == 0) {  // cosine-distributed
            const double r = std::sqrt(u.x), phi = 2 * std::numbers::pi * u.y;
            l = r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1.0 - u.x)) * d.n;
        } else {  // GGX normals, reflected
            const glm::dvec3 hl = lighting::sample_ggx(u.x, u.y, alpha);
            const glm::dvec3 h = hl.x * t + hl.y * b + hl.z * d.n;
            l = 2.0 * glm::dot(d.v, h) * h - d.v;
        }
        const double nl = glm::dot(d.n, l);
        if (nl <= 0.0) continue;
        const double pdf = 0.5 * pdf_cosine(nl) + 0.5 * pdf_ggx(l);
        if (!(pdf > 0.0)) continue;
        sum += unfiltered(l) * f(l) * nl / pdf;
    }
    return sum / static_cast<double>(samples) + discs(d, f);
}

}  // namespace fxview::reference
