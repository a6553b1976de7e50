#include "lighting/lobe_mass.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace fxview::lighting {
namespace {

constexpr double kPi = std::numbers::pi;

// Phong: l at polar angle θ about r is above the surface for the azimuths with
// cos θ (n·r) + sin θ sin ψ cos φ > 0 (ψ the angle between n and r): a closed fraction per θ;
// θ by 2048 midpoints of the lobe's own distribution (cos θ = (1 - u)^(1/(p+1))).
double phong_mass(double nv, double power) {
    const double c = nv, s = std::sqrt(std::max(0.0, 1.0 - nv * nv));
    constexpr int kSteps = 2048;
    double above = 0.0;
    for (int k = 0; k < kSteps; ++k) {
        const double cos_theta = std::pow(1.0 - (k + 0.5) / kSteps, 1.0 / (power + 1.0)), sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
        const double a = c * cos_theta, b = s * sin_theta;
        above += a >= b ? 1.0 : a <= -b ? 0.0 : std::acos(-a / b) / kPi;
    }
    return above / kSteps;
}

// Blinn: h about n distributed as (n·h)^p, l = v mirrored about h, dl = 4 (v·h) dh: a 256 x 64 grid of
// midpoints (the azimuth finer, where the horizon cuts).
double blinn_mass(double nv, double power) {
    const glm::dvec3 v(std::sqrt(std::max(0.0, 1.0 - nv * nv)), 0.0, nv);
    constexpr int kPolar = 64, kAzimuth = 256;
    static const std::array<double, kAzimuth> cosines = [] {
        std::array<double, kAzimuth> c{};
        for (int k = 0; k < kAzimuth; ++k) c[static_cast<size_t>(k)] = std::cos(2.0 * kPi * (k + 0.5) / kAzimuth);
        return c;
    }();
    double sum = 0.0;
    for (int i = 0; i < kPolar; ++i) {
        const double cos_theta = std::pow(1.0 - (i + 0.5) / kPolar, 1.0 / (power + 1.0)), sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
        for (int k = 0; k < kAzimuth; ++k) {
            // v lies in the xz plane: only the azimuth's cosine matters.
            const glm::dvec3 h(sin_theta * cosines[static_cast<size_t>(k)], 0.0, cos_theta);
            const double vh = glm::dot(v, h);
            if (vh > 0.0 && 2.0 * vh * h.z - v.z > 0.0) sum += 4.0 * vh;
        }
    }
    return sum / (kPolar * kAzimuth);
}

}  // namespace

double lobe_mass_row(double power) { return std::clamp(std::log2(std::max(power, 1.0)) / 8.0, 0.0, 1.0); }

DfgTable make_lobe_mass_table(int size) {
    DfgTable table;
    table.size = size;
    table.data.resize(static_cast<size_t>(size) * size);
    for (int j = 0; j < size; ++j) {
        const double power = std::exp2(8.0 * j / (size - 1));
        for (int i = 0; i < size; ++i) {
            const double nv = static_cast<double>(i) / (size - 1);
            table.data[static_cast<size_t>(j) * size + i] = glm::vec3(static_cast<float>(phong_mass(nv, power)), static_cast<float>(blinn_mass(nv, power)), 0.0f);
        }
    }
    return table;
}

}  // namespace fxview::lighting
