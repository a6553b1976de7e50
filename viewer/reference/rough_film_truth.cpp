#include "reference/rough_film_truth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lighting/environment_sources.hpp"
#include "lighting/image_based_lighting.hpp"
#include "reference/film_strata.hpp"
#include "reference/tangent_frame.hpp"

namespace fxview::reference {

std::vector<double> rough_film_radiance(const EnvironmentLookup& environment, const glm::dvec3& n, const glm::dvec3& v, double power,
                                        const std::function<double(double cos_h, int nm)>& reflectance, unsigned seed, int samples) {
    constexpr int first = lighting::SpectralForm::kFirstNm, last = lighting::SpectralForm::kLastNm, kAngles = 33;
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    glm::dvec3 x, y;
    duff_frame(r, x, y);
    const auto lobe = [&](const glm::dvec3& l) { return glm::dot(n, l) > 0.0 ? phong_lobe(r, l, power) : 0.0; };
    // Directions drawn as the lobe: cos = (1 − u)^(1/(p+1)) about r, density (p + 1)/2π cos^p.
    const auto draw = [&](const glm::dvec2& u, double& density) {
        const double c = std::pow(1.0 - u.x, 1.0 / (power + 1.0)), s = std::sqrt(std::max(0.0, 1.0 - c * c)), phi = 2.0 * std::numbers::pi * u.y;
        density = (power + 1.0) / (2.0 * std::numbers::pi) * std::pow(c, power);
        return s * std::cos(phi) * x + s * std::sin(phi) * y + c * r;
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
    constexpr int first = lighting::SpectralForm::kFirstNm, last = lighting::SpectralForm::kLastNm;
    const glm::dvec3 r = 2.0 * glm::dot(n, v) * n - v;
    glm::dvec3 x, y;
    duff_frame(r, x, y);
    // A Hammersley set turned by the seed (Cranley-Patterson), drawn as the lobe: every direction above
    // the surface counts alike.
    const glm::dvec2 turn(std::fmod(seed * 0.6180339887498949, 1.0), std::fmod(seed * 0.7548776662466927, 1.0));
    std::vector<double> cosines;
    for (int i = 0; i < samples; ++i) {
        const glm::dvec2 u = glm::fract(lighting::hammersley(static_cast<unsigned>(i), static_cast<unsigned>(samples)) + turn);
        const double c = std::pow(1.0 - u.x, 1.0 / (power + 1.0)), s = std::sqrt(std::max(0.0, 1.0 - c * c)), phi = 2.0 * std::numbers::pi * u.y;
        const glm::dvec3 l = s * std::cos(phi) * x + s * std::sin(phi) * y + c * r;
        if (glm::dot(n, l) > 0.0) cosines.push_back(std::clamp(glm::dot(v, glm::normalize(v + l)), 0.0, 1.0));
    }
    if (cosines.empty()) cosines.push_back(std::clamp(glm::dot(n, v), 0.0, 1.0));  // none above the surface: as a smooth film
    std::vector<double> mean(last - first + 1, 0.0);
    // As under an environment: the film at 33 angles across the directions' range, interpolated.
    constexpr int kAngles = 33;
    const auto [lowest, highest] = std::minmax_element(cosines.begin(), cosines.end());
    const double low = *lowest, step = (*highest - low) / (kAngles - 1);
    std::vector<double> weight(kAngles, 0.0);  // each angle's share of the directions (linear interpolation's weights)
    for (const double cos_h : cosines) {
        const double at = step > 0.0 ? (cos_h - low) / step : 0.0;
        const int below = std::clamp(static_cast<int>(std::floor(at)), 0, kAngles - 2);
        const double t = std::clamp(at - below, 0.0, 1.0);
        weight[static_cast<size_t>(below)] += 1.0 - t;
        weight[static_cast<size_t>(below + 1)] += t;
    }
    for (int a = 0; a < kAngles; ++a) {
        if (!(weight[static_cast<size_t>(a)] > 0.0)) continue;
        for (int nm = first; nm <= last; ++nm)
            mean[static_cast<size_t>(nm - first)] += weight[static_cast<size_t>(a)] * radiance(low + a * step, nm) / static_cast<double>(cosines.size());
    }
    return mean;
}

}  // namespace fxview::reference
