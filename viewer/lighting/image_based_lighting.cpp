#include "lighting/image_based_lighting.hpp"

#include "brdf/microfacet.hpp"
#include "brdf/models.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

namespace fxview::lighting {
namespace {

constexpr double kPi = std::numbers::pi;

std::array<double, 9> sh_basis(const glm::dvec3& d) {
    return {0.282095,
            0.488603 * d.y,
            0.488603 * d.z,
            0.488603 * d.x,
            1.092548 * d.x * d.y,
            1.092548 * d.y * d.z,
            0.315392 * (3.0 * d.z * d.z - 1.0),
            1.092548 * d.x * d.z,
            0.546274 * (d.x * d.x - d.y * d.y)};
}

// A tangent frame about n.
void frame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    const glm::dvec3 up = std::abs(n.y) < 0.999 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    t = glm::normalize(glm::cross(up, n));
    b = glm::cross(n, t);
}

// Trilinear between the mips of `chain` at fractional `lod`.
glm::vec3 sample_lod(const std::vector<FloatCube>& chain, const glm::dvec3& d, double lod) {
    lod = std::clamp(lod, 0.0, static_cast<double>(chain.size() - 1));
    const int l0 = static_cast<int>(lod), l1 = std::min(l0 + 1, static_cast<int>(chain.size()) - 1);
    const float a = static_cast<float>(lod - l0);
    return glm::mix(sample_bilinear(chain[static_cast<size_t>(l0)], d), sample_bilinear(chain[static_cast<size_t>(l1)], d), a);
}

}  // namespace

glm::dvec2 hammersley(unsigned i, unsigned n) {
    unsigned bits = i;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return {(i + 0.5) / n, bits * 2.3283064365386963e-10};
}

glm::dvec3 sample_ggx(double u1, double u2, double alpha) {
    const double phi = 2.0 * kPi * u2;
    const double cos_theta = std::sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1));
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

double ggx_d(double nh, double alpha) { return brdf::ggx_distribution(nh, alpha); }

double prefiltered_roughness(int level, int levels) {
    const double t = static_cast<double>(level) / (levels - 1);
    return t * t;
}

double prefiltered_lod(double roughness, int levels) { return std::sqrt(std::clamp(roughness, 0.0, 1.0)) * (levels - 1); }

PrefilteredEnvironment prefilter(const Environment& environment, int levels, int samples) {
    PrefilteredEnvironment out = prefilter_irradiance(environment);
    out.specular = prefilter_specular(environment, levels, samples);
    return out;
}

std::vector<FloatCube> prefilter_specular(const Environment& environment, int levels, int samples) {
    std::vector<FloatCube> out;
    const FloatCube& radiance = environment.radiance;
    std::vector<FloatCube> chain{radiance};
    while (chain.back().size > 1) chain.push_back(downsample(chain.back()));
    out.push_back(radiance);
    const double texel_angle = 4.0 * kPi / (6.0 * radiance.size * radiance.size);
    for (int level = 1; level < levels; ++level) {
        const double roughness = prefiltered_roughness(level, levels), alpha = roughness * roughness;
        FloatCube cube(std::max(1, radiance.size >> level));
        // The narrowest lobe needs few directions; wider ones many, or a bright small region (a window
        // left in the map) shows as blotches where the same directions of neighbouring texels catch it.
        const int count = level == 1 ? samples : samples * 4;
        std::vector<std::jthread> workers;
        for (int face = 0; face < 6; ++face)
            workers.emplace_back([&, face] {
                for (int y = 0; y < cube.size; ++y)
                    for (int x = 0; x < cube.size; ++x) {
                        const glm::dvec3 n = texel_direction(face, x, y, cube.size);
                        glm::dvec3 t, b;
                        frame(n, t, b);
                        glm::dvec3 sum(0.0);
                        double weight = 0.0;
                        for (int i = 0; i < count; ++i) {
                            const glm::dvec2 u = hammersley(static_cast<unsigned>(i), static_cast<unsigned>(count));
                            const glm::dvec3 hl = sample_ggx(u.x, u.y, alpha);
                            const glm::dvec3 h = hl.x * t + hl.y * b + hl.z * n;
                            const glm::dvec3 l = 2.0 * glm::dot(n, h) * h - n;
                            const double nl = glm::dot(n, l);
                            if (nl <= 0.0) continue;
                            // Filtered importance sampling: read the mip whose texels cover this sample's share of the lobe.
                            const double pdf = ggx_d(hl.z, alpha) / 4.0;
                            const double lod = 0.5 * std::log2(1.0 / (count * pdf * texel_angle)) + 1.0;
                            sum += nl * glm::dvec3(sample_lod(chain, l, lod));
                            weight += nl;
                        }
                        cube.at(face, x, y) = glm::vec3(weight > 0 ? sum / weight : sum);
                    }
            });
        workers.clear();
        out.push_back(std::move(cube));
    }
    return out;
}

PrefilteredEnvironment prefilter_irradiance(const Environment& environment) {
    PrefilteredEnvironment out;
    const FloatCube& radiance = environment.radiance;
    // SH projection with exact texel solid angles, then the cosine convolution (Ramamoorthi-Hanrahan);
    // the discs apart, in closed form.
    std::array<glm::dvec3, 9> projection{};
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < radiance.size; ++y)
            for (int x = 0; x < radiance.size; ++x) {
                const std::array<double, 9> basis = sh_basis(texel_direction(face, x, y, radiance.size));
                const double omega = texel_solid_angle(x, y, radiance.size);
                for (size_t k = 0; k < 9; ++k) projection[k] += basis[k] * omega * glm::dvec3(radiance.at(face, x, y));
            }
    for (const DiscLight& disc : environment.discs)
        out.disc_irradiance.emplace_back(glm::vec3(disc.direction), glm::vec3(disc.radiance * disc.solid_angle() / kPi));
    const double band[9] = {kPi, 2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4, kPi / 4, kPi / 4, kPi / 4, kPi / 4};
    for (size_t k = 0; k < 9; ++k) out.irradiance[k] = glm::vec3(projection[k] * band[k] / kPi);
    return out;
}

glm::dvec3 evaluate_irradiance(const std::array<glm::vec3, 9>& sh, const glm::dvec3& n) {
    const std::array<double, 9> basis = sh_basis(n);
    glm::dvec3 sum(0.0);
    for (size_t k = 0; k < 9; ++k) sum += basis[k] * glm::dvec3(sh[k]);
    return sum;
}

glm::dvec3 evaluate_irradiance(const PrefilteredEnvironment& environment, const glm::dvec3& n) {
    glm::dvec3 sum = glm::max(evaluate_irradiance(environment.irradiance, n), glm::dvec3(0.0));
    for (const auto& [direction, irradiance] : environment.disc_irradiance)
        sum += std::max(glm::dot(n, glm::dvec3(direction)), 0.0) * glm::dvec3(irradiance);
    return sum;
}

DfgTable make_dfg_table(int size, int samples) {
    DfgTable table;
    table.size = size;
    table.data.resize(static_cast<size_t>(size) * size);
    for (int j = 0; j < size; ++j) {
        // Texels at the ends of both ranges, so that n·v = 1 and roughness 1 are tabulated, not clamped.
        const double roughness = static_cast<double>(j) / (size - 1), alpha = roughness * roughness;
        for (int i = 0; i < size; ++i) {
            const double nv = std::max(static_cast<double>(i) / (size - 1), 1e-3);
            const glm::dvec3 v(std::sqrt(1.0 - nv * nv), 0.0, nv);
            double a = 0.0, b = 0.0;
            for (int k = 0; k < samples; ++k) {
                const glm::dvec2 u = hammersley(static_cast<unsigned>(k), static_cast<unsigned>(samples));
                const glm::dvec3 h = sample_ggx(u.x, u.y, alpha);
                const double vh = glm::dot(v, h);
                const glm::dvec3 l = 2.0 * vh * h - v;
                if (l.z <= 0.0 || vh <= 0.0) continue;
                // f cos / pdf with pdf = D (n·h) / (4 v·h): G (v·h) / ((n·h)(n·v)). G: height-correlated
                // Smith with α = roughness², as Filament's and glTF's image-based lighting (Karis keeps his
                // k = (roughness + 1)²/8 remap for analytic lights; with it a metal lost its grazing
                // brightening: gold at n·v 0.05 in the furnace (1, 0.74, 0.33) instead of (1, 0.95, 0.85)).
                const double weight = brdf::smith_ggx_correlated(l.z, nv, alpha) * vh / (h.z * nv);
                const double fc = std::pow(1.0 - vh, 5.0);
                a += (1.0 - fc) * weight;
                b += fc * weight;
            }
            // G by cosine-distributed directions (density (n·l)/π): the mean of (1 - v·h)⁵.
            double g = 0.0;
            for (int k = 0; k < samples; ++k) {
                const glm::dvec2 u = hammersley(static_cast<unsigned>(k), static_cast<unsigned>(samples));
                const double r = std::sqrt(u.x), phi = 2.0 * kPi * u.y;
                const glm::dvec3 l(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u.x)));
                g += std::pow(1.0 - std::clamp(glm::dot(v, glm::normalize(l + v)), 0.0, 1.0), 5.0);
            }
            // Single scattering reflects at most what arrives: the samples' estimate of a smooth lobe at
            // normal incidence (E → 1) may land 2e-4 above, which is noise.
            const double sum = (a + b) / samples, cap = sum > 1.0 ? 1.0 / sum : 1.0;
            table.data[static_cast<size_t>(j) * size + i] =
                glm::vec3(static_cast<float>(cap * a / samples), static_cast<float>(cap * b / samples), static_cast<float>(g / samples));
        }
    }
    return table;
}

glm::dvec3 DfgTable::lookup(double nv, double roughness) const {
    // GL's bilinear filter at (value (size - 1) + ½) / size: texel centres at the tabulated values.
    const double x = std::clamp(nv, 0.0, 1.0) * (size - 1), y = std::clamp(roughness, 0.0, 1.0) * (size - 1);
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const double ax = x - x0, ay = y - y0;
    const auto at = [&](int i, int j) {
        return glm::dvec3(data[static_cast<size_t>(std::clamp(j, 0, size - 1)) * size + static_cast<size_t>(std::clamp(i, 0, size - 1))]);
    };
    return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), ax), glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), ax), ay);
}

}  // namespace fxview::lighting
