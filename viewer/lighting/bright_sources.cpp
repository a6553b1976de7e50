#include "lighting/bright_sources.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lighting/cube_map.hpp"

namespace fxview::lighting {
namespace {

double luminance(const float* c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }
double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace

int extract_bright_sources(std::vector<RadianceSample>& samples, std::vector<DiscLight>& discs, const BrightSourceRules& rules) {
    if (samples.empty()) return 0;
    std::vector<double> lums;
    lums.reserve(samples.size());
    double power = 0;
    for (const RadianceSample& s : samples) {
        lums.push_back(luminance(s.rgb));
        power += lums.back() * s.solid_angle;
    }
    std::vector<double> sorted = lums;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double median = std::max(sorted[sorted.size() / 2], 1e-12);
    const double search = std::cos(rules.search_degrees * std::numbers::pi / 180.0);
    const double ring_outer = std::cos(1.5 * rules.search_degrees * std::numbers::pi / 180.0);
    int moved = 0;
    while (moved < rules.max_sources && power > 0) {
        const size_t peak = static_cast<size_t>(std::max_element(lums.begin(), lums.end()) - lums.begin());
        if (lums[peak] < rules.peak_over_median * median) break;
        const glm::dvec3 centre = samples[peak].direction;
        // The surroundings: the mean radiance of the ring just outside the search cone.
        glm::dvec3 ring(0.0);
        double ring_weight = 0;
        std::vector<size_t> inside;
        for (size_t i = 0; i < samples.size(); ++i) {
            const double c = glm::dot(samples[i].direction, centre);
            if (c >= search) inside.push_back(i);
            else if (c >= ring_outer) {
                ring += glm::dvec3(samples[i].rgb[0], samples[i].rgb[1], samples[i].rgb[2]) * samples[i].solid_angle;
                ring_weight += samples[i].solid_angle;
            }
        }
        const glm::dvec3 around = ring_weight > 0 ? ring / ring_weight : glm::dvec3(0.0);
        const double around_lum = luminance(around), excess_peak = lums[peak] - around_lum;
        glm::dvec3 excess(0.0), centroid(0.0);
        double core = 0;
        for (const size_t i : inside) {
            const glm::dvec3 value(samples[i].rgb[0], samples[i].rgb[1], samples[i].rgb[2]);
            const glm::dvec3 above = glm::max(value - around, glm::dvec3(0.0));
            excess += above * samples[i].solid_angle;
            centroid += luminance(above) * samples[i].solid_angle * samples[i].direction;
            if (lums[i] - around_lum > 0.5 * excess_peak) core += samples[i].solid_angle;
        }
        if (luminance(excess) < rules.min_power_share * power || core <= 0) break;
        for (const size_t i : inside) {  // the source's texels become its surroundings
            for (int c = 0; c < 3; ++c) samples[i].rgb[c] = static_cast<float>(std::min(static_cast<double>(samples[i].rgb[c]), around[c]));
            lums[i] = luminance(samples[i].rgb);
        }
        DiscLight disc;
        disc.direction = glm::normalize(centroid);
        disc.angular_radius = std::acos(std::clamp(1.0 - core / (2.0 * std::numbers::pi), -1.0, 1.0));
        disc.radiance = excess / disc.solid_angle();  // the same power over the disc's own solid angle
        discs.push_back(disc);
        ++moved;
    }
    return moved;
}

int extract_bright_sources(Environment& environment, const BrightSourceRules& rules) {
    FloatCube& cube = environment.radiance;
    std::vector<RadianceSample> samples;
    samples.reserve(static_cast<size_t>(6) * cube.size * cube.size);
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < cube.size; ++y)
            for (int x = 0; x < cube.size; ++x)
                samples.push_back({texel_direction(face, x, y, cube.size), texel_solid_angle(x, y, cube.size), &cube.at(face, x, y).x});
    return extract_bright_sources(samples, environment.discs, rules);
}

int extract_bright_sources_equirectangular(float* rgba, int width, int height, std::vector<DiscLight>& discs, const BrightSourceRules& rules) {
    std::vector<RadianceSample> samples;
    samples.reserve(static_cast<size_t>(width) * height);
    const double pi = std::numbers::pi;
    for (int y = 0; y < height; ++y) {
        const double theta = (y + 0.5) / height * pi;
        const double omega = (std::cos(static_cast<double>(y) / height * pi) - std::cos((y + 1.0) / height * pi)) * 2 * pi / width;
        for (int x = 0; x < width; ++x) {
            const double phi = ((x + 0.5) / width - 0.5) * 2 * pi;  // as from_equirectangular reads the image
            samples.push_back({{std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)}, omega,
                               rgba + (static_cast<size_t>(y) * width + x) * 4});
        }
    }
    return extract_bright_sources(samples, discs, rules);
}

}  // namespace fxview::lighting
