#include "fit/ashikhmin_fit.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace fxview::fit {
namespace {

constexpr double kPi = std::numbers::pi;

// One measured direction pair inside the limit, with its weight w·cos θi / Σw and the lobe's parts.
struct Sample {
    size_t value_index;
    double weight;
    glm::dvec3 l, v;
};

std::vector<Sample> samples_inside(const BrdfGrid& grid, double limit_deg) {
    const std::vector<double> w = solid_angle_weights(grid, limit_deg);
    double sum = 0;
    for (double x : w) sum += x;
    std::vector<Sample> samples;
    for (size_t i = 0; i < grid.theta_in.size(); ++i) {
        const glm::dvec3 l = grid.light(i);
        // Light at the horizon: weight cos θi = 0, and the lobe's max(n·l, n·v) may be 0 too (0 · ∞).
        if (grid.theta_in[i] > limit_deg || l.z < 1e-9) continue;
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p) {
                const double weight = w[o * grid.phi_out.size() + p];
                if (weight <= 0) continue;
                samples.push_back({grid.index(i, o, p), weight * l.z / sum, l, grid.camera(o, p)});
            }
    }
    return samples;
}

double mono(const std::array<double, 3>& rgb) { return (rgb[0] + rgb[1] + rgb[2]) / 3.0; }

// Stage 1 (eq. 4.26): parameters a = (ns, cd, cs) for the mean of the three channels.
struct MonochromeProblem {
    const BrdfGrid& grid;
    const std::vector<Sample>& samples;

    double model(const Sample& s, const Eigen::VectorXd& a) const { return a[1] / kPi + a[2] * ashikhmin_lobe(s.l, s.v, a[0]); }

    void residuals(const Eigen::VectorXd& a, Eigen::VectorXd& r) const {
        r.resize(static_cast<Eigen::Index>(samples.size()));
        for (size_t j = 0; j < samples.size(); ++j)
            r[static_cast<Eigen::Index>(j)] = samples[j].weight * (mono(grid.values[samples[j].value_index]) - model(samples[j], a));
    }

    // Eq. 4.29 (with the weights, and the sign of r = w (R − M)).
    void jacobian(const Eigen::VectorXd& a, Eigen::MatrixXd& d) const {
        d.resize(static_cast<Eigen::Index>(samples.size()), 3);
        for (size_t j = 0; j < samples.size(); ++j) {
            const Sample& s = samples[j];
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

double error_number(const BrdfGrid& grid, const std::vector<Sample>& samples, int channel /* -1: mean */, double ns, double cd,
                    double cs) {
    double sum = 0;
    for (const Sample& s : samples) {
        const auto& y = grid.values[s.value_index];
        const double measured = channel < 0 ? mono(y) : y[static_cast<size_t>(channel)];
        const double f = cd / kPi + cs * ashikhmin_lobe(s.l, s.v, ns);
        sum += (f - measured) * (f - measured);
    }
    return sum;
}

}  // namespace

double ashikhmin_lobe(const glm::dvec3& l, const glm::dvec3& v, double ns) {
    const glm::dvec3 h = glm::normalize(l + v);
    const double n_dot_h = std::max(h.z, 1e-4);
    return (ns + 1.0) / (8.0 * kPi) * std::pow(n_dot_h, ns) / (glm::dot(h, v) * std::max(l.z, v.z));
}

FitResult fit_ashikhmin_shirley(const BrdfGrid& measured, const FitOptions& options) {
    if (options.limit_deg <= 0 || options.limit_deg > 90) throw UsageError("fit: the limit angle must lie in (0, 90] degrees");
    if (options.iterations < 1) throw UsageError("fit: at least one iteration");
    const std::vector<Sample> samples = samples_inside(measured, options.limit_deg);
    if (samples.size() < 3) throw Error("fit: fewer than 3 samples inside the limit angle");

    FitResult result;
    result.samples_used = static_cast<int>(samples.size());
    MonochromeProblem problem{measured, samples};
    Eigen::VectorXd a(3);
    a << options.start_ns, options.start_cd, options.start_cs;
    LevenbergMarquardtOptions lm;
    lm.iterations = options.iterations;
    result.stage1 = levenberg_marquardt(problem, a, lm, [&](const Eigen::VectorXd& now) {
        result.error_per_iteration.push_back(std::sqrt(error_number(measured, samples, -1, now[0], now[1], now[2])));
    });
    result.ns = a[0];
    result.mono_cd = a[1];
    result.mono_cs = a[2];
    result.error_mono = std::sqrt(error_number(measured, samples, -1, a[0], a[1], a[2]));

    // Stage 2 (eq. 4.27, 4.30): with ns fixed the model is linear in (cd, cs); weighted least squares.
    Eigen::MatrixXd design(static_cast<Eigen::Index>(samples.size()), 2);
    for (size_t j = 0; j < samples.size(); ++j) {
        design(static_cast<Eigen::Index>(j), 0) = samples[j].weight / kPi;
        design(static_cast<Eigen::Index>(j), 1) = samples[j].weight * ashikhmin_lobe(samples[j].l, samples[j].v, result.ns);
    }
    const auto qr = design.colPivHouseholderQr();
    double rgb_sum = 0;
    for (int c = 0; c < 3; ++c) {
        Eigen::VectorXd target(static_cast<Eigen::Index>(samples.size()));
        for (size_t j = 0; j < samples.size(); ++j)
            target[static_cast<Eigen::Index>(j)] = samples[j].weight * measured.values[samples[j].value_index][static_cast<size_t>(c)];
        const Eigen::VectorXd x = qr.solve(target);
        result.cd[static_cast<size_t>(c)] = x[0];
        result.cs[static_cast<size_t>(c)] = x[1];
        rgb_sum += error_number(measured, samples, c, result.ns, x[0], x[1]);
    }
    result.error_rgb = std::sqrt(rgb_sum);

    result.rs = std::max({result.cs[0], result.cs[1], result.cs[2]});
    for (size_t c = 0; c < 3; ++c) {
        result.cs_renderer[c] = result.rs > 0 ? result.cs[c] / result.rs : 0.0;
        result.rd_renderer[c] = result.rs < 1 ? result.cd[c] / (1.0 - result.rs) : 0.0;
    }
    return result;
}

BrdfGrid evaluate_fit(const BrdfGrid& grid, const FitResult& fit) {
    BrdfGrid model = grid;
    for (size_t i = 0; i < grid.theta_in.size(); ++i)
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p) {
                const glm::dvec3 l = grid.light(i), v = grid.camera(o, p);
                const double lobe = l.z > 0 && v.z > 0 ? ashikhmin_lobe(l, v, fit.ns) : 0.0;
                for (size_t c = 0; c < 3; ++c) model.values[grid.index(i, o, p)][c] = fit.cd[c] / kPi + fit.cs[c] * lobe;
            }
    return model;
}

}  // namespace fxview::fit
