#include "fit/brdf_fit.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "brdf/microfacet.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"

namespace fxview::fit {
namespace {

constexpr double kPi = std::numbers::pi;
const char* kChannel[] = {"red", "green", "blue"};

double mono(const std::array<double, 3>& rgb) { return (rgb[0] + rgb[1] + rgb[2]) / 3.0; }

// Stage 1 (eq. 4.26): parameters a = (ns, cd, cs) for the mean of the three channels.
struct MonochromeProblem {
    const std::vector<Observation>& samples;

    double model(const Observation& s, const Eigen::VectorXd& a) const { return a[1] / kPi + a[2] * ashikhmin_lobe(s.l, s.v, a[0]); }

    void residuals(const Eigen::VectorXd& a, Eigen::VectorXd& r) const {
        r.resize(static_cast<Eigen::Index>(samples.size()));
        for (size_t j = 0; j < samples.size(); ++j)
            r[static_cast<Eigen::Index>(j)] = samples[j].weight * (mono(samples[j].value) - model(samples[j], a));
    }

    // Eq. 4.29 (with the weights, and the sign of r = w (R − M)).
    void jacobian(const Eigen::VectorXd& a, Eigen::MatrixXd& d) const {
        d.resize(static_cast<Eigen::Index>(samples.size()), 3);
        for (size_t j = 0; j < samples.size(); ++j) {
            const Observation& s = samples[j];
            const double lobe = ashikhmin_lobe(s.l, s.v, a[0]);
            const double n_dot_h = std::max(glm::normalize(s.l + s.v).z, 1e-4);
            // ∂/∂ns of (ns + 1)(n·h)^ns = (n·h)^ns (1 + (ns + 1) ln(n·h)); lobe carries (ns + 1)(n·h)^ns.
            const double d_ns = a[2] * lobe * (1.0 / (a[0] + 1.0) + std::log(n_dot_h));
            const auto row = static_cast<Eigen::Index>(j);
            d(row, 0) = -s.weight * d_ns;
            d(row, 1) = -s.weight / kPi;
            d(row, 2) = -s.weight * lobe;
        }
    }
};

// e² of the thesis' stage 1: the mean of RGB against its one cd, cs (eq. 4.1, unweighted).
double mean_error(const std::vector<Observation>& samples, double ns, double cd, double cs) {
    double sum = 0;
    for (const Observation& s : samples) {
        const double f = cd / kPi + cs * ashikhmin_lobe(s.l, s.v, ns);
        sum += (f - mono(s.value)) * (f - mono(s.value));
    }
    return sum;
}

// Seed 000's two stages: stage 1 fits (ns, cd, cs) to the mean of RGB by its Levenberg-Marquardt
// schedule; stage 2 solves cd and cs per channel with ns fixed (eq. 4.27, 4.30), unbounded.
void run_thesis(const std::vector<Observation>& samples, const FitOptions& options, FitResult& result) {
    MonochromeProblem problem{samples};
    Eigen::VectorXd a(3);
    a << options.start_ns, options.start_cd, options.start_cs;
    LevenbergMarquardtOptions lm;
    lm.iterations = options.iterations;
    result.stage1 = levenberg_marquardt(problem, a, lm, [&](const Eigen::VectorXd& now) {
        const double e = std::sqrt(mean_error(samples, now[0], now[1], now[2]));
        result.error_per_iteration.push_back(e);
        if (options.on_progress)
            options.on_progress({static_cast<double>(result.error_per_iteration.size()) / options.iterations, "stage 1", now[0],
                                 {now[1], now[1], now[1]}, {now[2], now[2], now[2]}, e * e, {now[0]}});
    });
    result.ns = a[0];
    result.mono_cd = a[1];
    result.mono_cs = a[2];
    result.solver = "thesis";
    result.stop_reason = "stage 1: " + std::to_string(options.iterations) + " iterations (" + std::to_string(result.stage1.accepted) +
                         " steps accepted), the thesis' only stop rule";

    Eigen::MatrixXd design(static_cast<Eigen::Index>(samples.size()), 2);
    for (size_t j = 0; j < samples.size(); ++j) {
        design(static_cast<Eigen::Index>(j), 0) = samples[j].weight / kPi;
        design(static_cast<Eigen::Index>(j), 1) = samples[j].weight * ashikhmin_lobe(samples[j].l, samples[j].v, result.ns);
    }
    const auto qr = design.colPivHouseholderQr();
    for (int c = 0; c < 3; ++c) {
        Eigen::VectorXd target(static_cast<Eigen::Index>(samples.size()));
        for (size_t j = 0; j < samples.size(); ++j)
            target[static_cast<Eigen::Index>(j)] = samples[j].weight * samples[j].value[static_cast<size_t>(c)];
        const Eigen::VectorXd x = qr.solve(target);
        result.cd[static_cast<size_t>(c)] = x[0];
        result.cs[static_cast<size_t>(c)] = x[1];
    }
    if (result.ns <= 0) result.warnings.push_back("ns <= 0: the model has no lobe (the thesis' solver is unbounded)");
    for (size_t k = 0; k < 3; ++k) {
        if (result.cd[k] < 0) result.warnings.push_back(std::string("cd (") + kChannel[k] + ") < 0: not a physical BRDF");
        if (result.cs[k] < 0) result.warnings.push_back(std::string("cs (") + kChannel[k] + ") < 0: not a physical BRDF");
    }
}

FitData fit_data(const std::vector<Observation>& samples) {
    FitData data;
    data.geometry.reserve(samples.size());
    data.values.reserve(samples.size());
    data.weights.reserve(samples.size());
    for (const Observation& s : samples) {
        data.geometry.push_back(sample_geometry(s.l, s.v));
        data.values.push_back(s.value);
        data.weights.push_back(s.weight);
    }
    return data;
}

void take(const SeparableSolution& s, FitResult& result) {
    result.shape = s.shape;
    result.ns = s.shape.at(0);
    result.cd = s.a;
    result.cs = s.b;
}

// The global optimum of the linear problem; with `polish_transform` set, the polish minimises the
// compressed residual instead, starting from `start` (the reweighted solution) when given.
void run_global(const FitModel& model, const FitData& data, const FitOptions& options, FitResult& result,
                const ResidualTransform& polish_transform = {}, const FitResult* start = nullptr) {
    SeparableSolution begin;
    if (start) {
        begin.shape = start->shape;
        begin.a = start->cd;
        begin.b = start->cs;
    }
    SeparableProgress progress;
    if (options.on_progress)
        progress = [&](double fraction, const char* stage, const std::vector<double>& shape, const std::array<double, 3>& a,
                       const std::array<double, 3>& b, double cost) { options.on_progress({fraction, stage, shape.at(0), a, b, cost, shape}); };
    const SeparableSolution s = solve_separable(model, data, polish_transform, start ? &begin : nullptr, progress);
    take(s, result);
    const BoundedReport& polish = s.polish;
    result.solver = "global";
    result.stop_reason = std::string("polish: ") + stop_reason_text(polish.reason) + " after " + std::to_string(polish.iterations) +
                         " iterations";
    result.converged = polish.converged();
    if (!result.converged) result.warnings.push_back("the polish did not converge: " + std::string(stop_reason_text(polish.reason)));
    const std::vector<ShapeParameter> shape = model.shape();
    const size_t K = shape.size();
    for (size_t k = 0; k < K; ++k)
        if (polish.at_lower[k] || polish.at_upper[k]) {
            char text[200];
            std::snprintf(text, sizeof text, "%s is at the end of its search range [%g, %g] (%g): the data have no lobe this model can describe",
                          shape[k].name.c_str(), shape[k].low, shape[k].high, result.shape[k]);
            result.warnings.push_back(text);
        }
    const auto names = model.scale_names();
    for (size_t c = 0; c < 3; ++c) {
        if (polish.at_lower[K + c]) result.warnings.push_back(names[0] + " (" + kChannel[c] + ") is at its bound 0");
        if (polish.at_lower[K + 3 + c]) result.warnings.push_back(names[1] + " (" + kChannel[c] + ") is at its bound 0: no specular lobe");
        if (polish.at_upper[K + 3 + c])
            result.warnings.push_back(names[1] + " (" + kChannel[c] + ") is at its bound 1" +
                                      (model.name() == kDefaultModel ? ": the renderer form's Rs = 1 leaves no diffuse part" : ""));
    }
    result.error_per_iteration.clear();
    for (const double cost : polish.cost_per_iteration) result.error_per_iteration.push_back(std::sqrt(cost));
}

// The robust weight ω(r) of a residual r at scale δ: ψ(r)/r of the loss.
// ρ of a loss (Huber: r²/2 inside δ, δ(|r| − δ/2) beyond; Cauchy: δ²/2 ln(1 + (r/δ)²); squared: r²/2).
double robust_rho(Loss loss, double r, double scale) {
    const double a = std::abs(r);
    if (loss == Loss::Huber) return a <= scale ? 0.5 * r * r : scale * (a - 0.5 * scale);
    if (loss == Loss::Cauchy) return 0.5 * scale * scale * std::log1p((r / scale) * (r / scale));
    return 0.5 * r * r;
}

double robust_weight(Loss loss, double r, double scale) {
    const double t = std::abs(r) / scale;
    if (loss == Loss::Huber) return t <= 1 ? 1.0 : 1.0 / t;
    if (loss == Loss::Cauchy) return 1.0 / (1.0 + t * t);
    return 1.0;
}

const char* residual_name(Residual r) { return r == Residual::CubeRoot ? "cube root" : r == Residual::Log ? "log" : "linear"; }
const char* loss_name(Loss l) { return l == Loss::Huber ? "Huber" : l == Loss::Cauchy ? "Cauchy" : "squared"; }


// A compressed residual and/or a robust loss. The shape is searched globally on the linear residual;
// from that optimum a bounded Levenberg-Marquardt minimises Σ (w_j (g(y) − g(f)))² itself (a local
// step: the compressed problem has no linear structure to search globally). A robust loss is
// iteratively reweighted least squares: each round sets ω_j from the current residuals and solves
// again with weights w_j ω_j^½, until no parameter moves by more than 1e-5 of itself.
// Each direction's residual for the robust loss: w_j √(mean over RGB of the transformed residual²).
std::vector<double> direction_residuals(const FitModel& model, const FitData& data, const ResidualTransform& transform, const FitResult& at) {
    std::vector<double> residuals(data.values.size());
    for (size_t j = 0; j < data.values.size(); ++j) {
        const auto f = model.evaluate(data.geometry[j], at.cd, at.cs, at.shape);
        double sum = 0;
        for (size_t c = 0; c < 3; ++c) {
            const double r = transform.value(data.values[j][c]) - transform.value(f[c]);
            sum += r * r;
        }
        residuals[j] = data.weights[j] * std::sqrt(sum / 3.0);
    }
    return residuals;
}

void run_reweighted(const FitModel& model, const FitData& data, const FitOptions& options, FitResult& result) {
    double mean = 0;
    for (const auto& y : data.values) mean += mono(y);
    mean /= static_cast<double>(data.values.size());
    const ResidualTransform transform{options.residual, 1e-3 * std::max(mean, 1e-12)};
    const std::vector<std::string> warnings = result.warnings;
    run_global(model, data, options, result);  // the linear least-squares optimum: the start
    std::vector<std::string> round_warnings = result.warnings;
    FitData robust = data;
    double scale = options.loss_scale;
    bool settled = false;
    const int rounds = options.loss == Loss::Squared ? 1 : 300;  // the reweighting converges linearly: Cauchy on poorly fitting data needs ~200
    for (int round = 1; round <= rounds && !settled; ++round) {
        if (options.loss != Loss::Squared) {
            const std::vector<double> residuals = direction_residuals(model, data, transform, result);
            if (!(scale > 0)) {  // Huber's 1.345 σ, σ from the median absolute residual of the start
                std::vector<double> sorted = residuals;
                std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
                scale = 1.345 * 1.4826 * std::max(sorted[sorted.size() / 2], 1e-300);
            }
            for (size_t j = 0; j < data.values.size(); ++j)
                robust.weights[j] = data.weights[j] * std::sqrt(robust_weight(options.loss, residuals[j], scale));
        }
        FitResult next;
        const FitResult current = result;
        run_global(model, robust, FitOptions{}, next, transform, &current);
        bool still = true;
        for (size_t k = 0; k < result.shape.size(); ++k) still = still && std::abs(next.shape[k] - result.shape[k]) <= 1e-5 * result.shape[k];
        for (size_t c = 0; c < 3; ++c)
            still = still && std::abs(next.cd[c] - result.cd[c]) <= 1e-8 + 1e-5 * result.cd[c] &&
                    std::abs(next.cs[c] - result.cs[c]) <= 1e-8 + 1e-5 * result.cs[c];
        settled = options.loss == Loss::Squared || still;  // least squares: one solve, nothing to reweight
        result.shape = next.shape;
        result.ns = next.ns;
        result.cd = next.cd;
        result.cs = next.cs;
        result.stop_reason = next.stop_reason;
        result.converged = next.converged;
        result.error_per_iteration = next.error_per_iteration;
        round_warnings = next.warnings;
        result.reweightings = options.loss == Loss::Squared ? 0 : round;
        if (options.on_progress)
            options.on_progress({std::min(0.6 + 0.004 * round, 0.99), "reweighting", result.ns, result.cd, result.cs, 0.0, result.shape});
    }
    result.warnings = warnings;
    result.warnings.insert(result.warnings.end(), round_warnings.begin(), round_warnings.end());
    if (!settled) {
        result.converged = false;
        result.warnings.push_back("the reweighting did not settle in 300 rounds");
    }
    result.stop_reason = (options.loss == Loss::Squared ? std::string() : std::to_string(result.reweightings) + " reweighting rounds, ") +
                         residual_name(options.residual) + " residual, " + loss_name(options.loss) + " loss; " + result.stop_reason;
    result.residual = residual_name(options.residual);
    result.loss = loss_name(options.loss);
    result.loss_scale_used = options.loss == Loss::Squared ? 0.0 : scale;
    // The cost of the problem solved: transformed residuals with the final robust weights.
    result.cost = separable_cost(model, robust, transform, result.shape, result.cd, result.cs);
    // And the objective itself, Σ ρ(r_j) with r_j = w_j √(mean over RGB of the transformed residual²):
    // what a robust fit minimises, comparable between models fitted with the same δ.
    result.objective = 0;
    for (const double r : direction_residuals(model, data, transform, result))
        result.objective += robust_rho(options.loss, r, options.loss == Loss::Squared ? 1.0 : scale);
}

// The clear coat of eq. 4.20: base_new = base / (1 − F(θi)), F the unpolarised Fresnel reflectance
// of the coat at the light's angle of incidence.
std::vector<Observation> without_clear_coat(const std::vector<Observation>& samples, double index) {
    std::vector<Observation> out = samples;
    for (Observation& s : out) {
        const double transmitted = 1.0 - brdf::fresnel_dielectric(index, s.l.z);
        for (double& x : s.value) x /= transmitted;
    }
    return out;
}

}  // namespace

double ashikhmin_lobe(const glm::dvec3& l, const glm::dvec3& v, double ns) {
    const glm::dvec3 h = glm::normalize(l + v);
    const double n_dot_h = std::max(h.z, 1e-4);
    return (ns + 1.0) / (8.0 * kPi) * std::pow(n_dot_h, ns) / (glm::dot(h, v) * std::max(l.z, v.z));
}

void validate(const FitOptions& options) {
    if (!(options.limit_deg > 0 && options.limit_deg <= 90)) throw UsageError("fit: the limit angle must lie in (0, 90] degrees");
    if (options.iterations < 1) throw UsageError("fit: at least one iteration");
    if (!(std::isfinite(options.start_ns) && options.start_ns > 0))
        throw UsageError("fit: the start exponent ns must be a positive number, not " + std::to_string(options.start_ns));
    if (!(std::isfinite(options.start_cd) && options.start_cd >= 0))
        throw UsageError("fit: the start cd must be a number >= 0, not " + std::to_string(options.start_cd));
    if (!(std::isfinite(options.start_cs) && options.start_cs >= 0))
        throw UsageError("fit: the start cs must be a number >= 0, not " + std::to_string(options.start_cs));
    if (!(std::isfinite(options.loss_scale) && options.loss_scale >= 0))
        throw UsageError("fit: the loss scale must be a number >= 0 (0: automatic), not " + std::to_string(options.loss_scale));
    find_model(options.model);  // an unknown name is a usage error
    if (options.solver == Solver::Thesis && options.model != kDefaultModel)
        throw UsageError("fit: the thesis solver fits the thesis' model (ashikhmin-fit) only; use the global solver for " + options.model);
    if (!(std::isfinite(options.clear_coat_index) && (options.clear_coat_index == 0 || (options.clear_coat_index > 1 && options.clear_coat_index <= 4))))
        throw UsageError("fit: the clear coat's refractive index must lie in (1, 4] (0: no coat), not " + std::to_string(options.clear_coat_index));
    if (options.solver == Solver::Thesis && (options.residual != Residual::Linear || options.loss != Loss::Squared))
        throw UsageError("fit: the thesis solver fits the linear residual by least squares only (use the global solver)");
}

FitResult fit_brdf(const BrdfGrid& measured, const FitOptions& options) {
    validate(options);
    return fit_brdf(observations(measured, options.limit_deg), options);
}

FitResult fit_brdf(const Observations& observed, const FitOptions& options) {
    validate(options);
    const std::shared_ptr<const FitModel> model = find_model(options.model);
    if (observed.samples.size() < 3) throw Error("fit: fewer than 3 samples inside the limit angle");
    const std::vector<Observation> samples =
        options.clear_coat_index > 0 ? without_clear_coat(observed.samples, options.clear_coat_index) : observed.samples;
    const FitData data = fit_data(samples);

    FitResult result;
    result.model = model->name();
    result.title = model->title();
    result.technique = model->technique();
    for (const ShapeParameter& p : model->shape()) result.shape_names.push_back(p.name);
    result.scale_names = model->scale_names();
    result.samples_used = static_cast<int>(samples.size());
    result.samples_masked = observed.masked;
    if (observed.masked > 0)
        result.warnings.push_back(std::to_string(observed.masked) + " of " + std::to_string(observed.total) +
                                  " samples inside the limit angle are negative (unmeasured) and left out");
    if (options.clear_coat_index > 0) {
        char text[240];
        std::snprintf(text, sizeof text,
                      "clear coat of index %g removed (eq. 4.20): the parameters describe the base under the coat; the technique renders "
                      "the base alone",
                      options.clear_coat_index);
        result.warnings.push_back(text);
    }
    const bool reweighted = options.solver == Solver::Global && (options.residual != Residual::Linear || options.loss != Loss::Squared);
    if (reweighted) {
        run_reweighted(*model, data, options, result);
    } else if (options.solver == Solver::Global) {
        run_global(*model, data, options, result);
    } else {
        run_thesis(samples, options, result);
        result.shape = {result.ns};
    }
    if (options.solver == Solver::Global) {
        result.mono_cd = mono(result.cd);
        result.mono_cs = mono(result.cs);
    }
    // Error numbers (eq. 4.1, unweighted) and the weighted RMS, on the linear residual.
    double rgb_sum = 0, mono_sum = 0, weighted = 0, weight_sum = 0;
    const std::array<double, 3> mono_a{result.mono_cd, result.mono_cd, result.mono_cd}, mono_b{result.mono_cs, result.mono_cs, result.mono_cs};
    for (size_t j = 0; j < samples.size(); ++j) {
        const auto f = model->evaluate(data.geometry[j], result.cd, result.cs, result.shape);
        const double w2 = data.weights[j] * data.weights[j];
        for (size_t c = 0; c < 3; ++c) {
            rgb_sum += (f[c] - data.values[j][c]) * (f[c] - data.values[j][c]);
            weighted += w2 * (f[c] - data.values[j][c]) * (f[c] - data.values[j][c]);
        }
        weight_sum += 3 * w2;
        const double m = model->evaluate(data.geometry[j], mono_a, mono_b, result.shape)[0];
        mono_sum += (m - mono(data.values[j])) * (m - mono(data.values[j]));
    }
    result.error_rgb = std::sqrt(rgb_sum);
    result.error_mono = std::sqrt(mono_sum);
    result.weighted_rms = std::sqrt(weighted / std::max(weight_sum, 1e-300));
    if (!reweighted) result.cost = weighted;
    if (options.solver == Solver::Global) {
        result.optimum_cost = result.cost;
    } else {
        // What the thesis' schedule reached, against the global optimum of the same problem.
        FitResult best;
        run_global(*model, data, FitOptions{}, best);  // quietly: the reference optimum
        result.optimum_cost = separable_cost(*model, data, {}, best.shape, best.cd, best.cs);
        if (result.cost > 1.001 * result.optimum_cost + 1e-300) {
            result.converged = false;
            char text[256];
            std::snprintf(text, sizeof text,
                          "the thesis' schedule stopped at a weighted cost %.3gx the optimum (the default solver finds ns %.4g)",
                          result.cost / std::max(result.optimum_cost, 1e-300), best.ns);
            result.warnings.push_back(text);
        }
    }

    const auto values = model->values(result.cd, result.cs, result.shape);
    const auto parameters = model->parameters();
    for (size_t i = 0; i < parameters.size(); ++i) result.parameters.push_back({parameters[i].name, parameters[i].uniform, values[i]});
    if (model->name() == kDefaultModel) {
        result.rs = std::max({result.cs[0], result.cs[1], result.cs[2]});
        if (result.rs >= 1) result.warnings.push_back("Rs = max(cs) >= 1: the renderer form (eq. 4.23) has no diffuse part");
        for (size_t c = 0; c < 3; ++c) {
            result.cs_renderer[c] = result.rs > 0 ? result.cs[c] / result.rs : 0.0;
            result.rd_renderer[c] = result.rs < 1 ? result.cd[c] / (1.0 - result.rs) : 0.0;
        }
    }
    if (model->technique() == "AshikhminShirley")
        for (size_t c = 0; c < 3; ++c) {
            if (result.cs[c] >= 1) result.warnings.push_back(std::string("Rs (") + kChannel[c] + ") = 1 leaves no diffuse part: Rd is reported as 0");
            else if (values[0][c] > 1) result.warnings.push_back(std::string("Rd (") + kChannel[c] + ") > 1: the substrate reflects more than it receives");
        }
    return result;
}

std::vector<FitResult> fit_all_models(const Observations& data, const FitOptions& options, bool isotropic_data) {
    std::vector<FitResult> results;
    const bool robust = options.solver == Solver::Global && options.loss != Loss::Squared;
    FitOptions shared = options;
    for (const std::string& name : model_names()) {
        if (isotropic_data && find_model(name)->anisotropic()) continue;
        if (options.solver == Solver::Thesis && name != kDefaultModel) continue;
        FitOptions one = shared;
        one.model = name;
        results.push_back(fit_brdf(data, one));
        // One robust scale δ for every model (the first's, from its least-squares residuals unless
        // given): models ranked by Σ ρ with different δ would be ranked by different objectives.
        if (robust && !(shared.loss_scale > 0)) shared.loss_scale = results.back().loss_scale_used;
    }
    // Best first by what was minimised (Σ ρ for a robust loss, the weighted cost otherwise); equal to
    // rounding (two exact fits of synthetic data): the model with fewer shape parameters first.
    const auto measure = [robust](const FitResult& r) { return robust ? r.objective : r.cost; };
    std::stable_sort(results.begin(), results.end(), [&measure](const FitResult& a, const FitResult& b) {
        const double tie = 1e-9 * std::max(measure(a), measure(b)) + 1e-24;
        if (std::abs(measure(a) - measure(b)) <= tie) return a.shape.size() < b.shape.size();
        return measure(a) < measure(b);
    });
    return results;
}

std::array<double, 3> evaluate_fit(const FitResult& fit, const glm::dvec3& l, const glm::dvec3& v) {
    if (!(l.z > 0 && v.z > 0)) return {0.0, 0.0, 0.0};
    return find_model(fit.model)->evaluate(sample_geometry(l, v), fit.cd, fit.cs, fit.shape);
}

BrdfGrid evaluate_fit(const BrdfGrid& grid, const FitResult& fit) {
    const std::shared_ptr<const FitModel> model = find_model(fit.model);
    BrdfGrid out = grid;
    for (size_t i = 0; i < grid.theta_in.size(); ++i)
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p) {
                const glm::dvec3 l = grid.light(i), v = grid.camera(o, p);
                out.values[grid.index(i, o, p)] =
                    l.z > 0 && v.z > 0 ? model->evaluate(sample_geometry(l, v), fit.cd, fit.cs, fit.shape) : std::array<double, 3>{};
            }
    return out;
}

}  // namespace fxview::fit
