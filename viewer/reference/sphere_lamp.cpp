#include "reference/sphere_lamp.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/tangent_frame.hpp"

namespace fxview::reference {
namespace {

constexpr double kPi = std::numbers::pi;

// The two lobes towards d, zero below the horizon.
glm::dvec2 lobes_towards(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& d, double power, double rounding) {
    if (glm::dot(n, d) <= 0.0) return glm::dvec2(0.0);
    const glm::dvec3 mirror = 2.0 * glm::dot(n, d) * n - d;
    return {std::pow(std::max(glm::dot(mirror, v), 0.0) * (1.0 + rounding), power),
            std::pow(std::max(glm::dot(n, glm::normalize(d + v)), 0.0) * (1.0 + rounding), power)};
}

}  // namespace

LampFactors sphere_lamp_factors(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double sin_alpha, double power, bool lobes,
                                double rounding) {
    LampFactors f;
    const double sin2 = sin_alpha * sin_alpha, cos_theta = glm::dot(n, l);
    if (cos_theta * cos_theta > sin2) {
        f.lambert = std::max(cos_theta, 0.0);
    } else {
        const double sin_theta = std::sqrt(std::max(1.0 - cos_theta * cos_theta, 1e-12));
        const double x = std::sqrt(std::max(1.0 / sin2 - 1.0, 1e-6)), y = std::clamp(-x * cos_theta / sin_theta, -1.0, 1.0);
        const double s = sin_theta * std::sqrt(1.0 - y * y), z = s / x;
        // As the GPU: (Snyder's E) / sin²α, the cancelling terms taken apart (sphere_lamp.glsl).
        f.lambert = std::max(cos_theta * std::acos(y) + z + (std::atan(z) - z) / sin2, 0.0) / kPi;
    }
    if (!lobes) return f;
    const double cos_alpha = std::sqrt(std::max(1.0 - sin2, 0.0)), versine = sin2 / (1.0 + cos_alpha), golden = kPi * (3.0 - std::sqrt(5.0));
    // The GPU's float may land on either side of a step of the count: `rounding` moves it as far (10
    // ulps) so that the slack sees both.
    const double wanted = 4.0 * kPi * sin2 * power * (1.0 + 10.0 * rounding);
    const double fewest = cos_theta * cos_theta * (1.0 + 10.0 * rounding) < sin2 ? 128.0 : 32.0;  // the horizon crosses the disc
    const int count = static_cast<int>(std::clamp(std::ceil(wanted), fewest, 256.0));
    glm::dvec3 x, y;
    duff_frame(l, x, y);
    glm::dvec2 sum(0.0);
    for (int j = 0; j < count; ++j) {
        const double c = 1.0 - (j + 0.5) / count * versine, sine = std::sqrt(std::max(1.0 - c * c, 0.0)), phi = golden * j;
        sum += lobes_towards(n, v, c * l + sine * (std::cos(phi) * x + std::sin(phi) * y), power, rounding);
    }
    sum *= 2.0 / (1.0 + cos_alpha) / count;
    f.phong = sum.x;
    f.blinn = sum.y;
    return f;
}

LampFactors sphere_lamp_integral(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double sin_alpha, double power) {
    constexpr int kRings = 128, kAzimuths = 256;
    const double alpha = std::asin(sin_alpha);
    glm::dvec3 x, y;
    duff_frame(l, x, y);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < kRings; ++i) {
        const double gamma = (i + 0.5) * alpha / kRings, weight = std::sin(gamma) * (alpha / kRings) * (2.0 * kPi / kAzimuths);
        for (int k = 0; k < kAzimuths; ++k) {
            const double phi = 2.0 * kPi * (k + 0.5) / kAzimuths;
            const glm::dvec3 d = std::cos(gamma) * l + std::sin(gamma) * (std::cos(phi) * x + std::sin(phi) * y);
            const glm::dvec2 lobe = lobes_towards(n, v, d, power, 0.0);
            sum += weight * glm::dvec3(std::max(glm::dot(n, d), 0.0), lobe.x, lobe.y);
        }
    }
    sum /= kPi * sin_alpha * sin_alpha;
    return {sum.x, sum.y, sum.z};
}

}  // namespace fxview::reference
