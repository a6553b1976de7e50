#include "reference/film_strata.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lighting/image_based_lighting.hpp"
#include "reference/tangent_frame.hpp"
#include "scene/light_geometry.hpp"

namespace fxview::reference {

// film_roughness.glsl's lobe: Phong of p = (1/α² − 1)/2 for α = roughness², within [1, 1e5].
double film_lobe_power(double roughness) {
    const double alpha = std::max(roughness * roughness, 1e-3);
    return std::clamp((1.0 / (alpha * alpha) - 1.0) / 2.0, 1.0, 1e5);
}

// film_roughness.glsl's film_rough_cosine: the mean and standard deviation of v·h over 32 of the lobe's
// directions above the surface.
glm::dvec2 film_rough_cosine(const glm::dvec3& n, const glm::dvec3& v, double power) {
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    glm::dvec3 x, y;
    duff_frame(r, x, y);
    double sum = 0.0, squares = 0.0, count = 0.0;
    for (unsigned i = 0; i < 32; ++i) {
        const glm::dvec3 l = phong_lobe_direction(r, x, y, lighting::hammersley(i, 32), power);
        if (glm::dot(n, l) <= 0.0) continue;
        const double c_h = std::clamp(glm::dot(v, glm::normalize(v + l)), 0.0, 1.0);
        sum += c_h;
        squares += c_h * c_h;
        count += 1.0;
    }
    if (!(count > 0.0)) return {std::clamp(glm::dot(n, v), 0.0, 1.0), 0.0};
    const double mean = sum / count;
    return {mean, std::sqrt(std::max(squares / count - mean * mean, 0.0))};
}

double film_points_lobe_power(double power, double solid, int points) { return std::min(power, 1.0 / std::max(0.36 * solid / points, 1e-12)); }

glm::dvec3 phong_lobe_direction(const glm::dvec3& r, const glm::dvec3& x, const glm::dvec3& y, const glm::dvec2& u, double power, double* cosine) {
    const double c = std::pow(1.0 - u.x, 1.0 / (power + 1.0)), sine = std::sqrt(std::max(0.0, 1.0 - c * c)), phi = 2.0 * std::numbers::pi * u.y;
    if (cosine) *cosine = c;
    return sine * std::cos(phi) * x + sine * std::sin(phi) * y + c * r;
}

// (r·l)^p, nothing behind r (also at p = 0, where pow(0, 0) would give 1).
double phong_lobe(const glm::dvec3& r, const glm::dvec3& l, double power) {
    const double c = glm::dot(r, l);
    return c > 0.0 ? std::pow(c, power) : 0.0;
}

FilmStrata film_rough_strata(const glm::dvec3& n, const glm::dvec3& v, double power, const glm::dvec2& seen, const EnvironmentLookup* sky,
                             const ShadingInput& in, double mirror_lamp) {
    constexpr double kPi = std::numbers::pi;
    const glm::dvec3 edges = seen.x + seen.y * glm::dvec3(-0.674, 0.0, 0.674);
    // A direction's shares of the four strata, split linearly across 0.1 σ about each edge (film_stratum_of).
    const double soft = std::max(0.1 * seen.y, 1e-6);
    const auto stratum_of = [&](double c_h) {
        const glm::dvec3 above = glm::clamp((c_h - edges) / soft + 0.5, 0.0, 1.0);
        return std::array<double, 4>{1.0 - above.x, above.x - above.y, above.y - above.z, above.z};
    };
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    glm::dvec3 x, y;
    duff_frame(r, x, y);
    FilmStrata strata;
    std::array<double, 4> count{}, light{}, light_c{}, light_c2{};
    double seam = 0.0;
    // Light of `amount` at angle c_h, shared among the strata as `at`: what sets each stratum's angle.
    const auto add_light = [&](const std::array<double, 4>& at, double amount, double c_h) {
        for (size_t s = 0; s < 4; ++s) {
            light[s] += at[s] * amount;
            light_c[s] += at[s] * amount * c_h;
            light_c2[s] += at[s] * amount * c_h * c_h;
        }
    };
    const auto add = [&](const std::array<double, 4>& at, const glm::dvec3& w, double c_h) {
        for (size_t s = 0; s < 4; ++s) strata.weights[s] += at[s] * w;
        add_light(at, w.x + w.y + w.z, c_h);  // the three spectra have luminance 1
    };
    const int samples = power >= 64.0 ? 32 : power >= 8.0 ? 64 : 256;  // spectral_lobe_samples()
    for (int i = 0; i < samples; ++i) {
        double c = 0.0;
        const glm::dvec3 l = phong_lobe_direction(r, x, y, lighting::hammersley(static_cast<unsigned>(i), samples), power, &c);
        const double density = (power + 1.0) / (2.0 * kPi) * std::pow(c, power);
        if (glm::dot(n, l) <= 0.0 || !(density > 0.0)) continue;
        double seam_here = 0.0;
        const glm::dvec3 w = sky ? sky->spectral_filtered(l, 1.0 / (samples * density), &seam_here) : glm::dvec3(1.0);
        const double c_h = std::clamp(glm::dot(v, glm::normalize(v + l)), 0.0, 1.0);
        const std::array<double, 4> at = stratum_of(c_h);
        add(at, w, c_h);
        for (size_t s = 0; s < 4; ++s) count[s] += at[s];
        seam += seam_here;
    }
    const double total = count[0] + count[1] + count[2] + count[3];
    if (!(total > 0.0)) {  // no direction above the surface: the mirror direction's angle, one stratum
        strata.cosine = {seen.x, 0.0, 0.0, 0.0};
        strata.share = {1.0, 0.0, 0.0, 0.0};
        strata.weights = {};
        if (sky) strata.weights[0] = sky->spectral_weights(r, &strata.seam);  // as a smooth film (a bump turned from the eye)
        strata.lamp[0] = mirror_lamp;
        return strata;
    }
    for (size_t s = 0; s < 4; ++s) {
        strata.share[s] = count[s] / total;
        strata.weights[s] /= total;
        light[s] /= total;
        light_c[s] /= total;
        light_c2[s] /= total;
    }
    strata.seam = sky ? seam / total * sky->intensity() : 0.0;
    // The disc lights' points, over the lobe's mass above the surface; a lobe narrower than the points'
    // cells widened (film_points_lobe_power).
    if (sky) {
        for (const EnvironmentLookup::DiscPoint& point : sky->spectral_disc_points()) {
            if (glm::dot(n, point.direction) <= 0.0) continue;
            const double seen_power = film_points_lobe_power(power, kPi * point.disc_radius * point.disc_radius, 16);
            const double mass = sky->spectral_lobe_mass(glm::dot(n, v), seen_power).x;
            if (!(mass > 0.0)) continue;
            const glm::dvec3 w = point.weights * (phong_lobe(r, point.direction, seen_power) / mass);
            const double c_h = std::clamp(glm::dot(v, glm::normalize(v + point.direction)), 0.0, 1.0);
            add(stratum_of(c_h), w, c_h);
        }
    }
    // The scene's sized light through the lobe at its points, each π L ΔΩ (r·l)^p / mass; the mass
    // 2π/(p+1) times the part of the lobe's directions above the surface.
    const bool flat_lamp = in.lamp.is_flat();
    if (flat_lamp || in.light_radius > 0.0) {
        const glm::dvec3 to_centre = in.light - in.position;
        const double distance = std::max(glm::length(to_centre), 1e-12);
        const glm::dvec3 c = to_centre / distance;
        glm::dvec3 cx, cy;
        duff_frame(c, cx, cy);
        const double sine = std::clamp(in.light_radius / distance, 0.0, 1.0), cosine = std::sqrt(1.0 - sine * sine), tangent = sine / std::max(cosine, 1e-6);
        const double solid = flat_lamp ? std::min(in.lamp.area() * std::max(-glm::dot(c, in.lamp.normal), 0.0) / (distance * distance), 2.0 * kPi)
                                       : 2.0 * kPi * sine * sine / (1.0 + cosine);
        const int points = flat_lamp ? 34 : 16;
        const double seen_power = film_points_lobe_power(power, solid, points);
        const double mass = 2.0 * kPi / (seen_power + 1.0) * total / samples;
        const double golden = kPi * (3.0 - std::sqrt(5.0));
        for (int j = 0; j < points; ++j) {
            glm::dvec3 l;
            double amount;  // L ΔΩ of the point
            if (flat_lamp) {
                const glm::dvec3 d = scene::flat_light_point(in.lamp, j, 34) - in.position;
                const double r2 = std::max(glm::dot(d, d), 1e-24);
                l = d / std::sqrt(r2);
                amount = in.lamp.radiance * in.lamp.area() * std::max(-glm::dot(l, in.lamp.normal), 0.0) / r2 / 34.0;
            } else {
                const double radius = std::sqrt((j + 0.5) / 16.0) * tangent, angle = golden * j;  // equal areas of the tangent plane
                l = glm::normalize(c + radius * (std::cos(angle) * cx + std::sin(angle) * cy));
                amount = 2.0 / (1.0 + cosine) / 16.0;  // a sphere of unit irradiance: L = 1 / (π sin²β)
            }
            if (glm::dot(n, l) <= 0.0) continue;
            const double w = kPi * amount * phong_lobe(r, l, seen_power) / mass, c_h = std::clamp(glm::dot(v, glm::normalize(v + l)), 0.0, 1.0);
            const std::array<double, 4> at = stratum_of(c_h);
            for (size_t s = 0; s < 4; ++s) strata.lamp[s] += at[s] * w;
            add_light(at, w, c_h);
        }
    }
    // Each stratum's angle weighted by its light; one without light keeps the middle of its edges.
    const std::array<double, 4> middle{edges.x - 0.5 * seen.y, 0.5 * (edges.x + edges.y), 0.5 * (edges.y + edges.z), edges.z + 0.5 * seen.y};
    for (size_t s = 0; s < 4; ++s) {
        const bool lit = light[s] > 0.0;
        strata.cosine[s] = std::clamp(lit ? light_c[s] / light[s] : middle[s], 0.0, 1.0);
        strata.spread[s] = lit ? std::sqrt(std::max(light_c2[s] / light[s] - strata.cosine[s] * strata.cosine[s], 0.0)) : 0.0;
    }
    return strata;
}

}  // namespace fxview::reference
