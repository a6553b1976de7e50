// Measured isotropic BRDFs on the grid of seed 000 (ch. 4.2.1, DOMAIN.md §8): the light on the −x
// axis at polar angles θi, the camera at (θo, φo) with φo from +x (0°) towards −x (180°), normal +z;
// RGB values (1/sr). The quarter sphere φo ∈ [0°, 180°] mirrors to the hemisphere.
// File format (open, since the thesis' was proprietary): CSV with the header
//   theta_in_deg,theta_out_deg,phi_out_deg,r,g,b
// one line per sample, any order, forming a complete grid; '#' lines are comments.
#pragma once
#include "core/limits.hpp"
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace fxview::fit {

struct BrdfGrid {
    std::vector<double> theta_in, theta_out, phi_out;  // degrees, ascending
    std::vector<std::array<double, 3>> values;          // index (i * theta_out.size() + o) * phi_out.size() + p

    size_t index(size_t i, size_t o, size_t p) const { return (i * theta_out.size() + o) * phi_out.size() + p; }
    size_t size() const { return theta_in.size() * theta_out.size() * phi_out.size(); }
    glm::dvec3 light(size_t i) const;   // unit vector towards the light
    glm::dvec3 camera(size_t o, size_t p) const;
};

// The thesis' grid: θi 0..90 in 5° (19), θo 0..90 in 2.5° (37), φo 0..180 in 36 steps; values zero.
BrdfGrid thesis_grid();
inline constexpr int kMaxGridSamplesPerAngle = 7201;
inline constexpr int kMaxGridDirections = 4'000'000;
// A uniform grid over the same ranges with `theta_in_count`, `theta_out_count`, `phi_out_count` samples.
// Throws UsageError below 2 samples per angle or beyond the bounds above.
BrdfGrid uniform_grid(int theta_in_count, int theta_out_count, int phi_out_count);
// True when the grid spans θ 0..90° and φ 0..180° with uniform steps (what a 3D texture of it needs).
bool is_uniform_full_grid(const BrdfGrid& grid);

// Reads / writes the CSV format above; read errors name the file and line (Error).
BrdfGrid read_brdf_grid(const std::string& path, const ResourceLimits& limits = {});
void write_brdf_grid(const BrdfGrid& grid, const std::string& path, int significant_digits = 17);  // 17: exact doubles

// The grid's directions filled with f(l, v) (e.g. an analytic model: synthetic "measurements").
BrdfGrid tabulate(const BrdfGrid& grid, const std::function<std::array<double, 3>(const glm::dvec3& l, const glm::dvec3& v)>& f);

// Solid angle of each camera sample (θo, φo) as a cell between the midpoints to its neighbours,
// clamped to [0°, limit] in θ and [0°, 180°] in φ (so edge samples get half a cell, corners a quarter;
// eq. 2.13: (cos θ1 − cos θ2)(φ2 − φ1)); samples beyond `limit_deg` get 0. Over the full quarter
// sphere they sum to π. Index o * phi_out.size() + p.
std::vector<double> solid_angle_weights(const BrdfGrid& grid, double limit_deg);

}  // namespace fxview::fit
