#include "reference/rough_film_truth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lighting/environment_sources.hpp"
#include "lighting/image_based_lighting.hpp"
#include "reference/film_strata.hpp"
#include "reference/tangent_frame.hpp"

namespace fxview::reference {

namespace {

struct Visit {
    double weight, cos_h;
};

// Σ weight · radiance(cos_h, nm) per nm of 360-830, the radiance taken at 33 angles across the visits'
// range and interpolated linearly between them (the film changes slowly with the angle).
std::vector<double> binned_sum(const std::vector<Visit>& visits, const std::function<double(double cos_h, int nm)>& radiance) {
    constexpr int first = lighting::SpectralForm::kFirstNm, last = lighting::SpectralForm::kLastNm, kAngles = 33;
    std::vector<double> sum(last - first + 1, 0.0);
    if (visits.empty()) return sum;
    double low = 1.0, high = 0.0;
    for (const Visit& visit : visits) low = std::min(low, visit.cos_h), high = std::max(high, visit.cos_h);
    const double step = (high - low) / (kAngles - 1);
    std::vector<double> weight(kAngles, 0.0);
    for (const Visit& visit : visits) {
        const double at = step > 0.0 ? (visit.cos_h - low) / step : 0.0;
        const int below = std::clamp(static_cast<int>(std::floor(at)), 0, kAngles - 2);
        const double t = std::clamp(at - below, 0.0, 1.0);
        weight[static_cast<size_t>(below)] += (1.0 - t) * visit.weight;
        weight[static_cast<size_t>(below + 1)] += t * visit.weight;
    }
    for (int a = 0; a < kAngles; ++a) {
        if (weight[static_cast<size_t>(a)] == 0.0) continue;
        for (int nm = first; nm <= last; ++nm) sum[static_cast<size_t>(nm - first)] += weight[static_cast<size_t>(a)] * radiance(low + a * step, nm);
    }
    return sum;
}

}  // namespace

std::vector<double> rough_film_radiance(const EnvironmentLookup& environment, const glm::dvec3& n, const glm::dvec3& v, double power,
                                        const std::function<double(double cos_h, int nm)>& reflectance, unsigned seed, int samples) {
    constexpr int first = lighting::SpectralForm::kFirstNm, last = lighting::SpectralForm::kLastNm, kAngles = 33;
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    glm::dvec3 x, y;
    duff_frame(r, x, y);
    const auto lobe = [&](const glm::dvec3& l) { return glm::dot(n, l) > 0.0 ? phong_lobe(r, l, power) : 0.0; };
    // Directions drawn as the lobe: cos = (1 − u)^(1/(p+1)) about r, density (p + 1)/2π cos^p.
    const auto draw = [&](const glm::dvec2& u, double& density) {
        double c = 0.0;
        const glm::dvec3 l = phong_lobe_direction(r, x, y, u, power, &c);
        density = (power + 1.0) / (2.0 * std::numbers::pi) * std::pow(c, power);
        return l;
    };
    struct Visit {
        double factor, cos_h;
        glm::dvec3 l;
    };
    std::vector<Visit> visits;
    double lowest = 1.0, highest = 0.0, total = 0.0;
    environment.visit_exact_integral(lobe, draw, samples, seed, [&](double factor, const glm::dvec3& l) {
        if (!(factor > 0.0)) return;
        const double cos_h = std::clamp(glm::dot(v, glm::normalize(v + l)), 0.0, 1.0);
        visits.push_back({factor, cos_h, l});
        lowest = std::min(lowest, cos_h);
        highest = std::max(highest, cos_h);
        total += factor;
    });
    // No direction of the lobe above the surface (a bump turned from the eye): as a smooth film, the
    // mirror direction at the eye's angle (film_rough_strata does the same).
    if (visits.empty() || !(total > 0.0)) {
        visits = {{1.0, std::clamp(glm::dot(n, v), 0.0, 1.0), r}};
        lowest = highest = visits.front().cos_h;
        total = 1.0;
    }
    std::vector<double> radiance(last - first + 1, 0.0);
    // The film's reflectance at 33 angles across the directions' range, per nm.
    const double step = (highest - lowest) / (kAngles - 1);
    std::vector<double> table(static_cast<size_t>(kAngles) * radiance.size());
    for (int a = 0; a < kAngles; ++a)
        for (int nm = first; nm <= last; ++nm) table[static_cast<size_t>(a) * radiance.size() + static_cast<size_t>(nm - first)] = reflectance(lowest + a * step, nm);
    for (const Visit& visit : visits) {
        const double at = step > 0.0 ? (visit.cos_h - lowest) / step : 0.0;
        const int below = std::clamp(static_cast<int>(std::floor(at)), 0, kAngles - 2);
        const double t = std::clamp(at - below, 0.0, 1.0);
        const glm::dvec3 w = environment.exact_spectral_weights(visit.l);
        for (int nm = first; nm <= last; ++nm) {
            const size_t i = static_cast<size_t>(nm - first);
            const double film = (1.0 - t) * table[static_cast<size_t>(below) * radiance.size() + i] + t * table[static_cast<size_t>(below + 1) * radiance.size() + i];
            radiance[i] += visit.factor * environment.exact_spectral_radiance(w, nm) * film;
        }
    }
    for (double& value : radiance) value /= total;
    return radiance;
}

std::vector<double> rough_film_uniform(const glm::dvec3& n, const glm::dvec3& v, double power, const std::function<double(double cos_h, int nm)>& radiance,
                                       unsigned seed, int samples) {
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    glm::dvec3 x, y;
    duff_frame(r, x, y);
    // A Hammersley set turned by the seed (Cranley-Patterson), drawn as the lobe: every direction above
    // the surface counts alike.
    const glm::dvec2 turn(std::fmod(seed * 0.6180339887498949, 1.0), std::fmod(seed * 0.7548776662466927, 1.0));
    std::vector<double> cosines;
    for (int i = 0; i < samples; ++i) {
        const glm::dvec2 u = glm::fract(lighting::hammersley(static_cast<unsigned>(i), static_cast<unsigned>(samples)) + turn);
        const glm::dvec3 l = phong_lobe_direction(r, x, y, u, power);
        if (glm::dot(n, l) > 0.0) cosines.push_back(std::clamp(glm::dot(v, glm::normalize(v + l)), 0.0, 1.0));
    }
    if (cosines.empty()) cosines.push_back(std::clamp(glm::dot(n, v), 0.0, 1.0));  // none above the surface: as a smooth film
    std::vector<Visit> visits;
    for (const double cos_h : cosines) visits.push_back({1.0 / static_cast<double>(cosines.size()), cos_h});
    return binned_sum(visits, radiance);
}

std::vector<double> rough_lamp_radiance(const ShadingInput& in, const glm::dvec3& n, const glm::dvec3& v, double power, double mirror_lamp,
                                        const std::function<double(double cos_h, int nm)>& radiance) {
    constexpr double kPi = std::numbers::pi;
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    glm::dvec3 x, y;
    duff_frame(r, x, y);
    // The lobe's mass above the surface: 2π/(p+1) times the part of 4096 of its directions there.
    int above = 0;
    for (unsigned i = 0; i < 4096; ++i) {
        above += glm::dot(n, phong_lobe_direction(r, x, y, lighting::hammersley(i, 4096), power)) > 0.0;
    }
    const double mass = 2.0 * kPi / (power + 1.0) * above / 4096.0;
    std::vector<Visit> visits;
    const auto visit = [&](const glm::dvec3& l, double radiance_solid_angle) {  // L ΔΩ of one cell
        if (glm::dot(n, l) <= 0.0 || !(radiance_solid_angle > 0.0)) return;
        visits.push_back({kPi * radiance_solid_angle * phong_lobe(r, l, power) / mass, std::clamp(glm::dot(v, glm::normalize(v + l)), 0.0, 1.0)});
    };
    if (!(mass > 0.0)) {
        visits.push_back({mirror_lamp, std::clamp(glm::dot(n, v), 0.0, 1.0)});
    } else if (in.lamp.is_flat()) {
        const bool disc = in.lamp.shape == scene::LightShape::Disc;
        const int rows = disc ? 32 : 48, columns = disc ? 64 : 48;
        const double cell = in.lamp.area() / (rows * columns);
        for (int i = 0; i < rows; ++i)
            for (int j = 0; j < columns; ++j) {
                const glm::dvec2 q = disc ? in.lamp.radius * std::sqrt((i + 0.5) / rows) *
                                                glm::dvec2(std::cos(2.0 * kPi * (j + 0.5) / columns), std::sin(2.0 * kPi * (j + 0.5) / columns))
                                          : in.lamp.half_size * glm::dvec2(2.0 * (i + 0.5) / rows - 1.0, 2.0 * (j + 0.5) / columns - 1.0);
                const glm::dvec3 d = in.lamp.centre + q.x * in.lamp.u + q.y * in.lamp.v - in.position;
                const double r2 = glm::dot(d, d);
                const glm::dvec3 l = d / std::sqrt(r2);
                visit(l, in.lamp.radiance * cell * std::max(-glm::dot(l, in.lamp.normal), 0.0) / r2);
            }
    } else if (in.light_radius > 0.0) {
        const glm::dvec3 to_centre = in.light - in.position;
        const double distance = glm::length(to_centre);
        const glm::dvec3 c = to_centre / distance;
        glm::dvec3 cx, cy;
        duff_frame(c, cx, cy);
        const double sine = std::min(in.light_radius / distance, 1.0), cos_beta = std::sqrt(1.0 - sine * sine);
        const double cell = 2.0 * kPi * (1.0 - cos_beta) / (32 * 64), light = 1.0 / (kPi * sine * sine);  // unit irradiance at normal incidence
        for (int i = 0; i < 32; ++i)
            for (int j = 0; j < 64; ++j) {
                const double cos_t = 1.0 - (i + 0.5) / 32.0 * (1.0 - cos_beta), sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
                const double phi = 2.0 * kPi * (j + 0.5) / 64.0;
                visit(cos_t * c + sin_t * (std::cos(phi) * cx + std::sin(phi) * cy), light * cell);
            }
    }
    return binned_sum(visits, radiance);
}

}  // namespace fxview::reference
