// Fitting the simplified Ashikhmin-Shirley model (seed 000 eq. 4.28) to a measured BRDF grid in the
// thesis' two stages (DOMAIN.md §8): (1) the mean of RGB with one cd, cs and the exponent ns by
// Levenberg-Marquardt (derivatives eq. 4.29); (2) with ns fixed, cd and cs per channel, a linear
// least-squares problem (eq. 4.30) solved exactly. Residuals eq. 4.25/4.26/4.27: solid-angle weight ×
// cos θi × (measured − model) / Σw, samples beyond the limit angle left out.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "fit/brdf_grid.hpp"
#include "fit/levenberg_marquardt.hpp"

namespace fxview::fit {

struct FitOptions {
    double limit_deg = 75.0;  // θi and θo beyond it are left out (0..90 in 5° steps in the thesis)
    int iterations = 500;
    double start_ns = 25.0, start_cd = 0.2, start_cs = 0.2;
};

struct FitResult {
    double ns = 0;
    std::array<double, 3> cd{}, cs{};
    double mono_cd = 0, mono_cs = 0;  // stage 1
    // For a renderer with a Fresnel weight (the thesis' shader, eq. 4.23/4.24): Rs = max(cs),
    // cs' = cs / Rs, cd' = cd / (1 − Rs); f = (1 − Rs) cd'/π + Rs cs' lobe is the same BRDF.
    double rs = 0;
    std::array<double, 3> rd_renderer{}, cs_renderer{};
    double error_mono = 0, error_rgb = 0;  // e = sqrt(Σ(f − y)²) over the samples used, unweighted (eq. 4.1)
    std::vector<double> error_per_iteration;  // stage 1's e after each iteration (fig. 5.2)
    int samples_used = 0;  // directions inside the limit
    LevenbergMarquardtReport stage1;
};

// The specular lobe of eq. 4.28 without cs: (ns + 1)/(8π) (n·h)^ns / ((h·v) max(n·l, n·v)), n = +z,
// with n·h clamped to 1e-4 (ch. 4.2.4) so that its logarithm exists.
double ashikhmin_lobe(const glm::dvec3& l, const glm::dvec3& v, double ns);

FitResult fit_ashikhmin_shirley(const BrdfGrid& measured, const FitOptions& options);

// The model's values on the measured grid (for previews and error maps).
BrdfGrid evaluate_fit(const BrdfGrid& grid, const FitResult& fit);

}  // namespace fxview::fit
