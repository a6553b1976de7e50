// The MERL BRDF database's binary format (Matusik et al. 2003, "A Data-Driven Reflectance Model"):
// three int32 dimensions (90, 90, 180), then 3 × 90 × 90 × 180 doubles (all red, then green, then
// blue) over (θh, θd, φd) in the half/difference parametrisation (Rusinkiewicz 1998), θh indexed
// non-linearly (index = sqrt(θh / 90° · 90²)). Lookups follow the database's reference reader
// BRDFRead.cpp: nearest lower bin, channel scales 1/1500, 1.15/1500, 1.66/1500, φd folded by
// reciprocity into [0°, 180°).
#pragma once
#include "core/limits.hpp"
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "fit/brdf_grid.hpp"

namespace fxview::fit {

struct MerlBrdf {
    std::vector<double> data;  // 3 × 90 × 90 × 180, as stored (unscaled)
    std::array<double, 3> lookup(const glm::dvec3& l, const glm::dvec3& v) const;  // RGB in 1/sr; 0 where unmeasured
    std::array<double, 3> bin(int h, int d, int p) const;  // RGB in 1/sr as stored: negative where unmeasured
};

constexpr int kMerlThetaH = 90, kMerlThetaD = 90, kMerlPhiD = 180;

// Bin of a direction pair (both unit vectors in the +z hemisphere): θh, θd and φd indices.
std::array<int, 3> merl_bins(const glm::dvec3& l, const glm::dvec3& v);

MerlBrdf read_merl(const std::string& path, const ResourceLimits& limits = {});                   // Error naming the file on bad size/data
void write_merl(const MerlBrdf& merl, const std::string& path);  // for tests and conversions

// The light and view directions at the centre of a bin: θh = ((h + ½)/90)² · 90° (the table's
// square-root index), θd = (d + ½)°, φd = (p + ½)°, φh = 0.
struct BinDirections {
    glm::dvec3 l, v;
    double theta_half, theta_diff;
};
BinDirections merl_bin_centre(int h, int d, int p);

// A MERL table of an analytic BRDF, each bin its value at the bin's centre (synthetic test data).
MerlBrdf tabulate_merl(const std::function<std::array<double, 3>(const glm::dvec3& l, const glm::dvec3& v)>& f);

// The MERL BRDF sampled at the directions of `grid` (e.g. thesis_grid()).
BrdfGrid merl_to_grid(const MerlBrdf& merl, const BrdfGrid& grid);

}  // namespace fxview::fit
