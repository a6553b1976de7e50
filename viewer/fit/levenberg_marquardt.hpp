// Levenberg-Marquardt as seed 000 runs it (eq. 4.8, ch. 4.2.4; DOMAIN.md §8), in the style of
// Eigen's functor-based solvers: a ← a − (DᵀD + λ·diag(DᵀD))⁻¹ Dᵀ r by Cholesky, D = ∂r/∂a;
// λ starts at 1e-3, halves after a better step (down to 1e-4) and doubles after a worse one (up to 1),
// which is rejected; a fixed number of iterations is the stop rule.
#pragma once
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <functional>
#include <vector>

namespace fxview::fit {

struct LevenbergMarquardtOptions {
    int iterations = 500;
    double lambda_start = 1e-3, lambda_min = 1e-4, lambda_max = 1.0;
};

struct LevenbergMarquardtReport {
    std::vector<double> cost;  // ||r||² after each iteration (the accepted parameters')
    int accepted = 0, rejected = 0;
    double lambda = 0;
};

// Functor: void residuals(const Eigen::VectorXd& a, Eigen::VectorXd& r) const;
//          void jacobian(const Eigen::VectorXd& a, Eigen::MatrixXd& d) const;   // d(i, j) = ∂r_i/∂a_j
// `after_iteration` (optional) sees the parameters after each iteration, e.g. to log an error number.
template <typename Functor>
LevenbergMarquardtReport levenberg_marquardt(const Functor& functor, Eigen::VectorXd& a, const LevenbergMarquardtOptions& options,
                                             const std::function<void(const Eigen::VectorXd&)>& after_iteration = {}) {
    LevenbergMarquardtReport report;
    double lambda = options.lambda_start;
    Eigen::VectorXd r, candidate_r;
    Eigen::MatrixXd d;
    functor.residuals(a, r);
    double cost = r.squaredNorm();
    bool fresh_jacobian = false;
    for (int iteration = 0; iteration < options.iterations; ++iteration) {
        if (!fresh_jacobian) {
            functor.jacobian(a, d);
            fresh_jacobian = true;
        }
        const Eigen::MatrixXd normal = d.transpose() * d;
        Eigen::MatrixXd damped = normal;
        damped.diagonal() += lambda * normal.diagonal();
        const Eigen::VectorXd step = damped.llt().solve(d.transpose() * r);
        const Eigen::VectorXd candidate = a - step;
        functor.residuals(candidate, candidate_r);
        const double candidate_cost = candidate_r.squaredNorm();
        if (std::isfinite(candidate_cost) && candidate_cost < cost) {
            a = candidate;
            r = candidate_r;
            cost = candidate_cost;
            fresh_jacobian = false;
            lambda = std::max(lambda / 2.0, options.lambda_min);
            ++report.accepted;
        } else {
            lambda = std::min(lambda * 2.0, options.lambda_max);
            ++report.rejected;
        }
        report.cost.push_back(cost);
        if (after_iteration) after_iteration(a);
    }
    report.lambda = lambda;
    return report;
}

}  // namespace fxview::fit
