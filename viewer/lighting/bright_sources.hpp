// Small bright sources of an environment image (the sun in a photographed sky, a lamp) taken out of
// its texels into disc lights, as the built-in sky keeps its sun: a source a few texels wide cannot
// pass through prefiltering without blotches (neighbouring texels' sample directions catch it or
// miss it) nor through order-2 SH without ringing, while a disc is integrated in closed form.
#pragma once
#include <vector>

#include "lighting/environment_sources.hpp"

namespace fxview::lighting {

struct BrightSourceRules {
    double peak_over_median = 200;  // a source's brightest texel, times the map's median luminance at least
    double min_power_share = 0.05;  // of the map's power (∫ L dω) that the source must carry
    double search_degrees = 6;      // the source's texels lie within this angle of its brightest one
    int max_sources = 4;
};

// A texel of some map: where it looks, how much of the sphere it covers, its radiance (changed in place).
struct RadianceSample {
    glm::dvec3 direction;
    double solid_angle;
    float* rgb;
};

// Moves each such source into `discs`: its power above the radiance around it (the mean of a ring
// 6-9° out) becomes a disc of the same power, direction (the power-weighted centroid) and solid angle
// (its texels brighter than half its peak); its texels are set to the surroundings. Returns how many.
int extract_bright_sources(std::vector<RadianceSample>& samples, std::vector<DiscLight>& discs, const BrightSourceRules& rules = {});
// The same on an environment's cube (into environment.discs).
int extract_bright_sources(Environment& environment, const BrightSourceRules& rules = {});
// The same on an equirectangular RGBA float image (-Z at its centre, +Y at the top), before it is
// resampled: the source's power is then the image's own, to the last pixel.
int extract_bright_sources_equirectangular(float* rgba, int width, int height, std::vector<DiscLight>& discs,
                                           const BrightSourceRules& rules = {});

}  // namespace fxview::lighting
