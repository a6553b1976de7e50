#include "brdf/direction_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "brdf/microfacet.hpp"

namespace fxview::brdf {

SampleSet sample_set(int strategy_index, int side, glm::dvec2 shift, double phi_i_degrees) {
    SampleSet set;
    set.side = side;
    set.shift = shift;
    set.phi_i_degrees = phi_i_degrees;
    if (strategy_index == 0) set.strategy = SamplingStrategy::Cosine;
    else if (strategy_index == 1) set.strategy = SamplingStrategy::Uniform;
    else if (strategy_index == kFileStrategy) set.strategy = SamplingStrategy::File;
    else {
        set.strategy = SamplingStrategy::HalfVector;
        set.alpha = kSampledLobeWidths[static_cast<size_t>(strategy_index - 2)];
    }
    return set;
}

glm::dvec3 incident_direction(double theta_degrees, double phi_degrees) {
    const double t = theta_degrees * std::numbers::pi / 180.0, p = phi_degrees * std::numbers::pi / 180.0;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

glm::dvec3 sampled_direction(const SampleSet& set, const glm::dvec3& l, int a, int b) {
    const auto wrap = [](double x) { return x - std::floor(x); };
    const double u = wrap((a + 0.5) / set.side + set.shift.x), w = wrap((b + 0.5) / set.side + set.shift.y);
    const double phi = 2.0 * std::numbers::pi * w;
    switch (set.strategy) {
        case SamplingStrategy::Cosine: {
            const double r = std::sqrt(u);
            return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(1.0 - u, 0.0))};
        }
        case SamplingStrategy::Uniform: {
            const double s = std::sqrt(std::max(1.0 - u * u, 0.0));
            return {s * std::cos(phi), s * std::sin(phi), u};
        }
        case SamplingStrategy::HalfVector: break;
        case SamplingStrategy::File: return {0.0, 0.0, -1.0};  // only the GPU knows it
    }
    // GGX's inverse CDF in cos²θh: ∫ D (n·h) dω over θh < θ is tan²θ / (α² + tan²θ).
    const double a2 = set.alpha * set.alpha, c2 = (1.0 - u) / (1.0 + (a2 - 1.0) * u), sh = std::sqrt(std::max(1.0 - c2, 0.0));
    const glm::dvec3 h(sh * std::cos(phi), sh * std::sin(phi), std::sqrt(c2));
    return 2.0 * glm::dot(l, h) * h - l;
}

double strategy_pdf(int strategy_index, const glm::dvec3& l, const glm::dvec3& v) {
    if (v.z <= 0) return 0.0;
    if (strategy_index == 0) return v.z / std::numbers::pi;
    if (strategy_index == 1) return 0.5 / std::numbers::pi;
    if (strategy_index >= kSamplingStrategies) return 0.0;  // the file's own: only the GPU knows it
    const glm::dvec3 sum = l + v;
    const double length = glm::length(sum);
    if (length < 1e-12) return 0.0;
    const glm::dvec3 h = sum / length;
    const double v_dot_h = glm::dot(v, h);
    if (h.z <= 0 || v_dot_h <= 0) return 0.0;
    // dω_v = 4 (v·h) dω_h for a reflection about h.
    return ggx_distribution(h.z, kSampledLobeWidths[static_cast<size_t>(strategy_index - 2)]) * h.z / (4.0 * v_dot_h);
}

double mis_factor(int strategy_index, const glm::dvec3& l, const glm::dvec3& v, double file_pdf) {
    double squares = 0, own = 0;
    if (file_pdf >= 0.0) {
        squares = file_pdf * file_pdf;
        if (strategy_index == kFileStrategy) own = file_pdf;
    }
    for (int k = 0; k < kSamplingStrategies; ++k) {
        const double p = strategy_pdf(k, l, v);
        squares += p * p;
        if (k == strategy_index) own = p;
    }
    return squares > 0 ? own / squares : 0.0;
}

}  // namespace fxview::brdf
