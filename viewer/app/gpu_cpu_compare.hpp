// The GPU-vs-CPU comparison (docs/cpu-reference.md): render a technique into a float target that
// also captures the shared vertex stage's outputs, shade every covered pixel again on the CPU with
// the technique's reference, and measure the differences.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "app/scene_options.hpp"
#include "image/image.hpp"

namespace fxview::app {

struct CompareResult {
    std::string technique;
    bool has_reference = false;
    long pixels = 0;  // covered pixels compared
    double max_abs_error = 0, mean_abs_error = 0;
    struct {
        int x = -1, y = -1;
        std::array<double, 4> gpu{}, cpu{};
    } worst_pixel;
    long mismatched_8bit = 0;  // pixels whose displayed 8-bit value differs by more than one code
    long exceeding = 0;        // pixels whose error is above the tolerance (plus their slack)
    long pixels_within_slack = 0;  // pixels above the tolerance but within their slack (a jump, a sensitive highlight)
    double tolerance = 0;
    std::string tolerance_reason;
    bool pass = false;
    image::FloatImage heat_map;  // error / tolerance per pixel (RGB), black where nothing is covered

    // With ground_truth: how far the CPU reference (the technique's own approximation, e.g. the split
    // sum) is from the integral it stands for (Monte Carlo), as CIEDE2000 of the radiances taken as
    // colours (white: radiance 1). Absent where the technique approximates nothing.
    struct GroundTruth {
        std::string method;  // the reference's truth_method
        long pixels = 0;
        double mean_delta_e = 0, p95_delta_e = 0, max_delta_e = 0;  // against the mean of two estimates
        // The estimate's own noise (half the two estimates' ΔE00), and the errors beyond twice it.
        double mean_noise_delta_e = 0, p95_noise_delta_e = 0, mean_delta_e_beyond_noise = 0;
        long pixels_beyond_noise = 0;
        int worst_x = -1, worst_y = -1;
        std::array<double, 3> worst_reference{}, worst_truth{};
        image::FloatImage heat_map;  // ΔE00: blue 0, yellow 2, red 4 and beyond
    };
    std::optional<GroundTruth> ground_truth;
};

// `technique` empty: the request's technique, else the effect's first. `reference_sets` are
// NAME=VALUE assignments given to the CPU side only (to show that a comparison can fail).
CompareResult compare_technique(const RenderRequest& request, const std::string& technique,
                                const std::vector<std::string>& reference_sets, bool ground_truth = false);
std::vector<std::string> technique_names(const EffectOptions& effect);

}  // namespace fxview::app
