// Fitting the simplified Ashikhmin-Shirley model (seed 000 eq. 4.28) to a measured BRDF grid in the
// thesis' two stages (DOMAIN.md §8): (1) the mean of RGB with one cd, cs and the exponent ns by
// Levenberg-Marquardt (derivatives eq. 4.29); (2) with ns fixed, cd and cs per channel, a linear
// least-squares problem (eq. 4.30) solved exactly. Residuals eq. 4.25/4.26/4.27: solid-angle weight ×
// cos θi × (measured − model) / Σw, samples beyond the limit angle left out.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "fit/brdf_grid.hpp"
#include "fit/levenberg_marquardt.hpp"
#include "fit/merl.hpp"

namespace fxview::fit {

// global: the default. The model is linear in cd and cs, so for each ns the best scales per channel
//   are a bounded linear least-squares problem solved exactly (cd >= 0, 0 <= cs <= 1, the renderer
//   form's Rs <= 1); ns is searched over its whole range on a log scale (20 points per decade from
//   1e-2 to 1e6), refined by golden-section search, and everything is polished together by a bounded
//   Levenberg-Marquardt (bounded_levenberg_marquardt.hpp). It reaches the global optimum of the
//   weighted RGB cost and reports why it stopped and which parameters sit at a bound.
// thesis: seed 000's two stages with its λ schedule, as its figures were made; reported against the
//   global optimum, so that a stall is never silent.
enum class Solver { Global, Thesis };

// The residual's scale (Ngan et al. 2005 compare them): linear (the thesis' eq. 4.25), or compressed
// so that the highlight's peak does not outweigh the rest: cube root or log of (value + ε), ε = 1e-3 ×
// the data's mean value (so that values near 0 keep a finite slope).
enum class Residual { Linear, CubeRoot, Log };
// The loss on each sample's residual: least squares, or robust against outliers (Huber: linear beyond
// the scale; Cauchy: logarithmic). Solved by iteratively reweighted least squares.
enum class Loss { Squared, Huber, Cauchy };

// Where a running fit is, for a progress display (a plugin's worker thread, docs/plugins.md).
struct FitProgress {
    double fraction = 0;  // 0..1 of the expected work
    std::string stage;    // "search", "polish", "stage 1"
    double ns = 0;
    std::array<double, 3> cd{}, cs{};  // the current best scales (the thesis' stage 1: the mean's)
    double cost = 0;                   // the current weighted cost (the thesis' stage 1: e²)
};

struct FitOptions {
    double limit_deg = 75.0;  // θi and θo beyond it are left out (0..90 in 5° steps in the thesis)
    int iterations = 500;     // the thesis solver's stage-1 iterations
    double start_ns = 25.0, start_cd = 0.2, start_cs = 0.2;  // the thesis solver's start
    Solver solver = Solver::Global;
    Residual residual = Residual::Linear;  // the global solver only
    Loss loss = Loss::Squared;             // the global solver only
    double loss_scale = 0;  // robust losses: the residual where they turn; 0: 1.345 × the residuals' robust σ (MAD), Huber's choice
    // Called between steps; it may throw (e.g. plugin::Cancelled) to stop the fit.
    std::function<void(const FitProgress&)> on_progress;
};

// The search range of ns (the global solver's bounds).
constexpr double kMinExponent = 1e-2, kMaxExponent = 1e6;

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
    size_t samples_masked = 0;  // unmeasured samples left out
    LevenbergMarquardtReport stage1;  // the thesis solver's stage 1

    // The problem both solvers solve: the weighted RGB cost Σ_c Σ_j (w_j (y_jc − f_jc))² (eq. 4.27);
    // with a compressed residual or a robust loss, Σ (w_j ω_j^½ (g(y) − g(f)))² with the final robust
    // weights ω_j.
    double cost = 0;
    double optimum_cost = 0;  // the global search's cost (for the thesis solver: what it could have reached)
    std::string solver;       // "global" or "thesis"
    std::string stop_reason;  // why the last stage stopped
    bool converged = true;
    std::string residual = "linear", loss = "squared";
    double loss_scale_used = 0;  // robust losses: the scale applied
    int reweightings = 0;        // iteratively reweighted least squares: the outer iterations
    std::vector<std::string> warnings;  // parameters at a bound, a stall, a model outside its assumptions
};

// Validates the options as a user gave them (non-finite or negative starts, limit outside (0, 90]):
// UsageError.
void validate(const FitOptions& options);

// One measured direction pair: light and view (unit vectors, +z hemisphere), RGB in 1/sr, and its
// weight in the residual (eq. 4.25: the sample's measure × cos θi, normalised over the samples).
struct Observation {
    glm::dvec3 l, v;
    double weight;
    std::array<double, 3> value;
};

struct Observations {
    std::vector<Observation> samples;  // the ones fitted
    size_t total = 0;                  // samples in the data
    size_t masked = 0;                 // unmeasured (negative in a MERL file): counted, never fitted
    size_t outside_limit = 0;          // beyond the limit angle or at the horizon
};

// A grid: the thesis' weights (camera solid angle × cos θi).
Observations observations(const BrdfGrid& grid, double limit_deg);
// A MERL file at full density: every measured bin at its centre, weighted by its measure in
// (ωi, ωo) × cos θi; no resampling.
Observations observations(const MerlBrdf& merl, double limit_deg);

// The specular lobe of eq. 4.28 without cs: (ns + 1)/(8π) (n·h)^ns / ((h·v) max(n·l, n·v)), n = +z,
// with n·h clamped to 1e-4 (ch. 4.2.4) so that its logarithm exists.
double ashikhmin_lobe(const glm::dvec3& l, const glm::dvec3& v, double ns);

FitResult fit_ashikhmin_shirley(const BrdfGrid& measured, const FitOptions& options);
FitResult fit_ashikhmin_shirley(const Observations& data, const FitOptions& options);

// The model's values on the measured grid (for previews and error maps).
BrdfGrid evaluate_fit(const BrdfGrid& grid, const FitResult& fit);

}  // namespace fxview::fit
