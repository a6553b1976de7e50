// Fitting an analytic BRDF model (fit_model.hpp; the default is the thesis' simplified
// Ashikhmin-Shirley, seed 000 eq. 4.28) to a measured BRDF. Residuals eq. 4.25/4.26/4.27: solid-angle
// weight × cos θi × (measured − model) / Σw, samples beyond the limit angle left out. Two solvers: the
// global one (separable_solver.hpp) for every model, and the thesis' two stages (DOMAIN.md §8) for its
// own model: (1) the mean of RGB with one cd, cs and ns by its Levenberg-Marquardt schedule (eq. 4.29);
// (2) with ns fixed, cd and cs per channel by linear least squares (eq. 4.30).
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "fit/brdf_grid.hpp"
#include "fit/fit_model.hpp"
#include "fit/levenberg_marquardt.hpp"
#include "fit/merl.hpp"
#include "fit/separable_solver.hpp"

namespace fxview::fit {

// global: the default, for every model. The models are linear in their two scales per channel, so
//   for each shape the best scales are a bounded linear least-squares problem solved exactly (e.g.
//   cd >= 0, 0 <= cs <= 1, the renderer form's Rs <= 1); the shape (ns; nu, nv; alpha) is searched over
//   its whole range on a log scale and everything is polished together by a bounded
//   Levenberg-Marquardt (separable_solver.hpp). It reaches the global optimum of the weighted RGB cost
//   and reports why it stopped and which parameters sit at a bound.
// thesis: seed 000's two stages with its λ schedule, as its figures were made (its own model only);
//   reported against the global optimum, so that a stall is never silent.
enum class Solver { Global, Thesis };

// The residual's scale (Ngan et al. 2005 compare them; enum Residual in separable_solver.hpp): linear
// (the thesis' eq. 4.25), or compressed so that the highlight's peak does not outweigh the rest: cube
// root or log of (value + ε), ε = 1e-3 × the data's mean value (values near 0 keep a finite slope).
// The loss on each sample's residual: least squares, or robust against outliers (Huber: linear beyond
// the scale; Cauchy: logarithmic). Solved by iteratively reweighted least squares.
enum class Loss { Squared, Huber, Cauchy };

// Where a running fit is, for a progress display (a plugin's worker thread, docs/plugins.md).
struct FitProgress {
    double fraction = 0;  // 0..1 of the expected work
    std::string stage;    // "search", "polish", "stage 1"
    double ns = 0;        // the first shape parameter
    std::array<double, 3> cd{}, cs{};  // the current best scales (the thesis' stage 1: the mean's)
    double cost = 0;                   // the current weighted cost (the thesis' stage 1: e²)
    std::vector<double> shape;         // every shape parameter
};

struct FitOptions {
    std::string model = kDefaultModel;  // fit_model.hpp
    double limit_deg = 75.0;  // θi and θo beyond it are left out (0..90 in 5° steps in the thesis)
    int iterations = 500;     // the thesis solver's stage-1 iterations
    double start_ns = 25.0, start_cd = 0.2, start_cs = 0.2;  // the thesis solver's start
    Solver solver = Solver::Global;
    Residual residual = Residual::Linear;  // the global solver only
    Loss loss = Loss::Squared;             // the global solver only
    double loss_scale = 0;  // robust losses: the residual where they turn; 0: 1.345 × the residuals' robust σ (MAD), Huber's choice
    // The clear-coat preprocessing of eq. 4.19-4.22: the data are the base under a clear coat of this
    // refractive index (Fresnel removed, as the thesis' lacquer files); each value is divided by
    // 1 − F(θi) and the model fits that base. 0: none.
    double clear_coat_index = 0;
    // Called between steps; it may throw (e.g. plugin::Cancelled) to stop the fit.
    std::function<void(const FitProgress&)> on_progress;
};

// The search range of ns (the global solver's bounds).
constexpr double kMinExponent = 1e-2, kMaxExponent = 1e6;

// One fitted parameter as the model's technique reads it.
struct FittedParameter {
    std::string name, uniform;
    std::vector<double> values;  // r, g, b or one number
};

struct FitResult {
    std::string model, title, technique;  // the model fitted, what it is, its technique in analytic.fx
    std::vector<double> shape;            // its shape parameters (fit_model.hpp)
    std::vector<std::string> shape_names;
    std::array<std::string, 2> scale_names;
    std::vector<FittedParameter> parameters;  // as the technique reads them
    double ns = 0;                     // shape[0] (the thesis' exponent for its model)
    std::array<double, 3> cd{}, cs{};  // the model's two scales per channel (the thesis' cd and cs; kd and F0, ...)
    double mono_cd = 0, mono_cs = 0;  // stage 1
    // The thesis' model only: for a renderer with a Fresnel weight (its shader, eq. 4.23/4.24): Rs = max(cs),
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
    double weighted_rms = 0;  // √(Σ w² (y − f)² / (3 Σ w²)), linear residuals: the ranking's measure in 1/sr
    double optimum_cost = 0;  // the global search's cost (for the thesis solver: what it could have reached)
    std::string solver;       // "global" or "thesis"
    std::string stop_reason;  // why the last stage stopped
    bool converged = true;
    std::string residual = "linear", loss = "squared";
    double loss_scale_used = 0;  // robust losses: the scale applied
    // Robust losses: the objective minimised, Σ ρ(w_j |r_j|) (brdf_fit.cpp); what --model all ranks by.
    double objective = 0;
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
    size_t masked = 0;                 // unmeasured (negative) inside the limit angle: counted, warned, never fitted
    size_t outside_limit = 0;          // beyond the limit angle, at or below the horizon (MERL's negative markers there)
};

// A grid: the thesis' weights (camera solid angle × cos θi).
Observations observations(const BrdfGrid& grid, double limit_deg);
// A MERL file at full density: every measured bin at its centre, weighted by its measure in
// (ωi, ωo) × cos θi; no resampling.
Observations observations(const MerlBrdf& merl, double limit_deg);

// The specular lobe of eq. 4.28 without cs: (ns + 1)/(8π) (n·h)^ns / ((h·v) max(n·l, n·v)), n = +z,
// with n·h clamped to 1e-4 (ch. 4.2.4) so that its logarithm exists.
double ashikhmin_lobe(const glm::dvec3& l, const glm::dvec3& v, double ns);

FitResult fit_brdf(const BrdfGrid& measured, const FitOptions& options);
FitResult fit_brdf(const Observations& data, const FitOptions& options);

// `--model all`: every model fitted with the same options (an anisotropic model only on data that can
// show anisotropy), best weighted cost first.
std::vector<FitResult> fit_all_models(const Observations& data, const FitOptions& options, bool isotropic_data);

// The model's values on the measured grid (for previews and error maps) and at one direction pair.
BrdfGrid evaluate_fit(const BrdfGrid& grid, const FitResult& fit);
std::array<double, 3> evaluate_fit(const FitResult& fit, const glm::dvec3& l, const glm::dvec3& v);

}  // namespace fxview::fit
