// Levenberg-Marquardt with box bounds, in the style of Eigen's functor-based solvers: minimise
// ||r(a)||² subject to lower <= a <= upper. Each step solves (JᵀJ + λ diag(JᵀJ)) δ = −Jᵀr over the
// parameters not held at a bound (a parameter is held where it sits on a bound and the gradient
// pushes it outwards), then projects a + δ onto the box; a step that lowers the cost is taken and
// λ shrinks, otherwise λ grows (Marquardt's schedule, no cap). Stops, and says why, on a small
// projected gradient, a small step, a small relative decrease of the cost, or the iteration limit.
// Unlike the thesis' schedule (levenberg_marquardt.hpp) it cannot leave the box and cannot stall at
// a capped λ.
#pragma once
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <concepts>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace fxview::fit {

struct BoundedOptions {
    int max_iterations = 200;
    double gradient_tolerance = 1e-10;  // on max |projected gradient| · max(|a|, 1) / max(cost, tiny)
    double step_tolerance = 1e-12;      // on ||δ|| / (||a|| + step_tolerance)
    double cost_tolerance = 1e-14;      // on the relative decrease of an accepted step
    double lambda_start = 1e-3;
};

enum class StopReason { Gradient, Step, Cost, Iterations, NoDescent };

inline const char* stop_reason_text(StopReason reason) {
    switch (reason) {
        case StopReason::Gradient: return "projected gradient below tolerance";
        case StopReason::Step: return "step below tolerance";
        case StopReason::Cost: return "relative cost decrease below tolerance";
        case StopReason::Iterations: return "iteration limit reached (not converged)";
        case StopReason::NoDescent: return "no step lowers the cost any more (lambda at its limit)";
    }
    return "?";
}

struct BoundedReport {
    StopReason reason = StopReason::Iterations;
    int iterations = 0, accepted = 0, evaluations = 0;
    double cost = 0;
    std::vector<double> cost_per_iteration;  // after each iteration
    std::vector<bool> at_lower, at_upper;    // per parameter, at the end
    bool converged() const { return reason != StopReason::Iterations; }
};

// A problem with many residuals may hand over its normal equations instead of its Jacobian (which
// would not fit in memory): double cost(a) and double normal_equations(a, JᵀJ, Jᵀr) returning the cost.
template <typename Functor>
concept NormalEquationsProblem = requires(const Functor& f, const Eigen::VectorXd& a, Eigen::MatrixXd& m, Eigen::VectorXd& g) {
    { f.cost(a) } -> std::convertible_to<double>;
    { f.normal_equations(a, m, g) } -> std::convertible_to<double>;
};

template <typename Functor>
double problem_cost(const Functor& functor, const Eigen::VectorXd& a) {
    if constexpr (NormalEquationsProblem<Functor>) {
        return functor.cost(a);
    } else {
        Eigen::VectorXd r;
        functor.residuals(a, r);
        return r.squaredNorm();
    }
}

template <typename Functor>
void problem_normal_equations(const Functor& functor, const Eigen::VectorXd& a, Eigen::MatrixXd& normal, Eigen::VectorXd& gradient) {
    if constexpr (NormalEquationsProblem<Functor>) {
        functor.normal_equations(a, normal, gradient);
    } else {
        Eigen::VectorXd r;
        Eigen::MatrixXd jacobian;
        functor.residuals(a, r);
        functor.jacobian(a, jacobian);
        normal = jacobian.transpose() * jacobian;
        gradient = jacobian.transpose() * r;
    }
}

// Functor: void residuals(const Eigen::VectorXd& a, Eigen::VectorXd& r) const;
//          void jacobian(const Eigen::VectorXd& a, Eigen::MatrixXd& j) const;   // j(i, k) = ∂r_i/∂a_k
// or a NormalEquationsProblem.
template <typename Functor>
BoundedReport bounded_levenberg_marquardt(const Functor& functor, Eigen::VectorXd& a, const Eigen::VectorXd& lower,
                                          const Eigen::VectorXd& upper, const BoundedOptions& options = {},
                                          const std::function<void(const Eigen::VectorXd&, double cost)>& after_iteration = {}) {
    const Eigen::Index n = a.size();
    a = a.cwiseMax(lower).cwiseMin(upper);
    BoundedReport report;
    double cost = problem_cost(functor, a), lambda = options.lambda_start;
    ++report.evaluations;
    bool fresh = false;
    Eigen::VectorXd gradient;  // Jᵀr = ½ ∇cost
    Eigen::MatrixXd jtj;
    std::vector<bool> held(static_cast<size_t>(n));
    for (report.iterations = 0; report.iterations < options.max_iterations;) {
        if (!fresh) {
            problem_normal_equations(functor, a, jtj, gradient);
            fresh = true;
            // Held: on a bound with the descent direction (−gradient) pointing out of the box.
            double projected = 0;
            for (Eigen::Index k = 0; k < n; ++k) {
                const bool out_low = a[k] <= lower[k] && gradient[k] > 0, out_high = a[k] >= upper[k] && gradient[k] < 0;
                held[static_cast<size_t>(k)] = out_low || out_high;
                if (!held[static_cast<size_t>(k)]) projected = std::max(projected, std::abs(gradient[k]) * std::max(std::abs(a[k]), 1.0));
            }
            if (projected <= options.gradient_tolerance * std::max(cost, std::numeric_limits<double>::min())) {
                report.reason = StopReason::Gradient;
                break;
            }
        }
        ++report.iterations;
        if (after_iteration) after_iteration(a, cost);  // may throw to cancel
        Eigen::MatrixXd normal = jtj;
        Eigen::VectorXd rhs = -gradient;
        for (Eigen::Index k = 0; k < n; ++k) {
            normal(k, k) += lambda * std::max(normal(k, k), 1e-300);
            if (held[static_cast<size_t>(k)]) {  // freeze: δ_k = 0
                normal.row(k).setZero();
                normal.col(k).setZero();
                normal(k, k) = 1.0;
                rhs[k] = 0.0;
            }
        }
        const Eigen::VectorXd candidate = (a + normal.ldlt().solve(rhs)).cwiseMax(lower).cwiseMin(upper);
        const double step = (candidate - a).norm();
        if (step <= options.step_tolerance * (a.norm() + options.step_tolerance)) {
            report.reason = StopReason::Step;
            break;
        }
        const double candidate_cost = problem_cost(functor, candidate);
        ++report.evaluations;
        if (std::isfinite(candidate_cost) && candidate_cost < cost) {
            const double decrease = (cost - candidate_cost) / cost;
            a = candidate;
            cost = candidate_cost;
            fresh = false;
            lambda = std::max(lambda / 3.0, 1e-12);
            ++report.accepted;
            report.cost_per_iteration.push_back(cost);
            if (decrease <= options.cost_tolerance) {
                report.reason = StopReason::Cost;
                break;
            }
        } else {
            lambda *= 4.0;
            report.cost_per_iteration.push_back(cost);
            if (lambda > 1e16) {
                report.reason = StopReason::NoDescent;
                break;
            }
        }
    }
    report.cost = cost;
    report.at_lower.resize(static_cast<size_t>(n));
    report.at_upper.resize(static_cast<size_t>(n));
    for (Eigen::Index k = 0; k < n; ++k) {
        report.at_lower[static_cast<size_t>(k)] = a[k] <= lower[k];
        report.at_upper[static_cast<size_t>(k)] = a[k] >= upper[k];
    }
    return report;
}

}  // namespace fxview::fit
