#include "fit/ashikhmin_fit.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <limits>
#include <string>
#include <numbers>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "fit/bounded_levenberg_marquardt.hpp"

namespace fxview::fit {
namespace {

constexpr double kPi = std::numbers::pi;

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

double error_number(const std::vector<Observation>& samples, int channel /* -1: mean */, double ns, double cd,
                    double cs) {
    double sum = 0;
    for (const Observation& s : samples) {
        const auto& y = s.value;
        const double measured = channel < 0 ? mono(y) : y[static_cast<size_t>(channel)];
        const double f = cd / kPi + cs * ashikhmin_lobe(s.l, s.v, ns);
        sum += (f - measured) * (f - measured);
    }
    return sum;
}

// The weighted RGB cost, from explicit residuals.
double weighted_cost(const std::vector<Observation>& samples, double ns, const std::array<double, 3>& cd,
                     const std::array<double, 3>& cs) {
    double sum = 0;
    for (const Observation& s : samples) {
        const double lobe = ashikhmin_lobe(s.l, s.v, ns);
        for (size_t c = 0; c < 3; ++c) {
            const double r = s.weight * (s.value[c] - (cd[c] / kPi + cs[c] * lobe));
            sum += r * r;
        }
    }
    return sum;
}

// The residual's scale g and its slope: g(y) − g(f) is what is fitted.
struct Transform {
    Residual kind = Residual::Linear;
    double epsilon = 0;
    double value(double x) const {
        switch (kind) {
            case Residual::CubeRoot: return std::cbrt(x + epsilon);
            case Residual::Log: return std::log(std::max(x, 0.0) + epsilon);
            default: return x;
        }
    }
    double slope(double x) const {
        switch (kind) {
            case Residual::CubeRoot: return 1.0 / (3.0 * std::pow(std::cbrt(x + epsilon), 2.0));
            case Residual::Log: return 1.0 / (std::max(x, 0.0) + epsilon);
            default: return 1.0;
        }
    }
};

// The global solver. The lobe at sample j is (ns + 1) g_j (n·h_j)^ns: g_j and ln(n·h_j) are kept so
// that a new ns costs one exp per sample.
class GlobalFit {
public:
    explicit GlobalFit(const std::vector<Observation>& samples, Transform transform = {}) : samples_(samples), transform_(transform) {
        for (const Observation& s : samples) {
            const glm::dvec3 h = glm::normalize(s.l + s.v);
            log_n_dot_h_.push_back(std::log(std::max(h.z, 1e-4)));
            geometry_.push_back(1.0 / (8.0 * kPi * glm::dot(h, s.v) * std::max(s.l.z, s.v.z)));
        }
    }

    double lobe(size_t j, double ns) const { return (ns + 1.0) * geometry_[j] * std::exp(ns * log_n_dot_h_[j]); }

    struct Scales {
        std::array<double, 3> cd{}, cs{};
        double cost = 0;  // from the normal equations (for the search; the final cost is recomputed)
    };

    // For a fixed ns, per channel: min over cd >= 0, 0 <= cs <= 1 of the quadratic
    // q = yy − 2 cd bd − 2 cs bs + A cd² + 2 B cd cs + C cs². Convex over a box: the optimum is the
    // unconstrained one if feasible, else the best of the edges' own minima.
    // Σ over the samples of the quadratic's coefficients (one pass, on every core).
    struct Moments {
        double a = 0, b = 0, c = 0;
        std::array<double, 3> bd{}, bs{}, yy{};
        Moments& operator+=(const Moments& o) {
            a += o.a;
            b += o.b;
            c += o.c;
            for (size_t k = 0; k < 3; ++k) {
                bd[k] += o.bd[k];
                bs[k] += o.bs[k];
                yy[k] += o.yy[k];
            }
            return *this;
        }
    };

    Scales best_scales(double ns) const {
        const Moments m = parallel_sum<Moments>(samples_.size(), [&](size_t begin, size_t end) {
            Moments part;
            for (size_t j = begin; j < end; ++j) {
                const double w2 = samples_[j].weight * samples_[j].weight, l = lobe(j, ns);
                part.a += w2 / (kPi * kPi);
                part.b += w2 * l / kPi;
                part.c += w2 * l * l;
                const auto& y = samples_[j].value;
                for (size_t k = 0; k < 3; ++k) {
                    part.bd[k] += w2 * y[k] / kPi;
                    part.bs[k] += w2 * y[k] * l;
                    part.yy[k] += w2 * y[k] * y[k];
                }
            }
            return part;
        });
        const double a = m.a, b = m.b, c = m.c;
        const auto& bd = m.bd;
        const auto& bs = m.bs;
        const auto& yy = m.yy;
        Scales out;
        for (size_t k = 0; k < 3; ++k) {
            const auto q = [&](double d, double s) { return yy[k] - 2 * d * bd[k] - 2 * s * bs[k] + a * d * d + 2 * b * d * s + c * s * s; };
            double best = q(0, 0), best_d = 0, best_s = 0;
            const auto consider = [&](double d, double s) {
                if (!(d >= 0 && s >= 0 && s <= 1)) return;
                const double value = q(d, s);
                if (value < best) {
                    best = value;
                    best_d = d;
                    best_s = s;
                }
            };
            const double det = a * c - b * b;
            if (det > 1e-14 * a * c) consider((bd[k] * c - bs[k] * b) / det, (bs[k] * a - bd[k] * b) / det);
            if (c > 0) consider(0, std::clamp(bs[k] / c, 0.0, 1.0));
            if (a > 0) consider(std::max(bd[k] / a, 0.0), 0);
            if (a > 0) consider(std::max((bd[k] - b) / a, 0.0), 1);
            out.cd[k] = best_d;
            out.cs[k] = best_s;
            out.cost += best;
        }
        return out;
    }

    // The exponent with the lowest profile cost: a log-spaced scan, then golden-section search
    // between the best point's neighbours.
    double search_exponent(const std::function<void(const FitProgress&)>& on_progress) const {
        const double lo = std::log(kMinExponent), hi = std::log(kMaxExponent);
        const int points = static_cast<int>(std::round(20 * std::log10(kMaxExponent / kMinExponent)));
        const auto profile = [this](double log_ns) { return best_scales(std::exp(log_ns)).cost; };
        int best = 0;
        double best_cost = std::numeric_limits<double>::infinity();
        for (int i = 0; i <= points; ++i) {
            const double cost = profile(lo + (hi - lo) * i / points);
            if (cost < best_cost) {
                best_cost = cost;
                best = i;
            }
            if (on_progress && i % 10 == 0) {
                const double ns = std::exp(lo + (hi - lo) * best / points);
                const Scales s = best_scales(ns);
                on_progress({0.6 * i / points, "search", ns, s.cd, s.cs, best_cost});
            }
        }
        double from = lo + (hi - lo) * std::max(best - 1, 0) / points, to = lo + (hi - lo) * std::min(best + 1, points) / points;
        const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
        for (int i = 0; i < 50 && to - from > 1e-10; ++i) {
            const double p = to - ratio * (to - from), q = from + ratio * (to - from);
            if (profile(p) < profile(q)) to = q;
            else from = p;
        }
        return std::exp(0.5 * (from + to));
    }

    // The polish's parameters p = (ln ns, cd r g b, cs r g b); residuals w (y − f) for every sample and
    // channel, handed over as normal equations: a Jacobian of 3 × 1.1 million rows (a MERL file)
    // would not fit in memory.
    struct Normal {
        double cost = 0;
        Eigen::Matrix<double, 7, 7> jtj = Eigen::Matrix<double, 7, 7>::Zero();
        Eigen::Matrix<double, 7, 1> jtr = Eigen::Matrix<double, 7, 1>::Zero();
        Normal& operator+=(const Normal& o) {
            cost += o.cost;
            jtj += o.jtj;
            jtr += o.jtr;
            return *this;
        }
    };

    Normal accumulate(const Eigen::VectorXd& p, bool derivatives) const {
        const double ns = std::exp(p[0]);
        return parallel_sum<Normal>(samples_.size(), [&](size_t begin, size_t end) {
            Normal part;
            for (size_t j = begin; j < end; ++j) {
                const double l = lobe(j, ns), w = samples_[j].weight;
                // ∂lobe/∂ln ns = ns ∂lobe/∂ns = lobe · ns (1/(ns + 1) + ln n·h)
                const double d_lobe = l * ns * (1.0 / (ns + 1.0) + log_n_dot_h_[j]);
                for (size_t k = 0; k < 3; ++k) {
                    const auto ki = static_cast<Eigen::Index>(k);
                    const double f = p[1 + ki] / kPi + p[4 + ki] * l;
                    const double r = w * (transform_.value(samples_[j].value[k]) - transform_.value(f));
                    part.cost += r * r;
                    if (!derivatives) continue;
                    // The row's three non-zeros: ∂r/∂ln ns, ∂r/∂cd_k, ∂r/∂cs_k (times g'(f) for a compressed residual).
                    const std::array<Eigen::Index, 3> column = {0, 1 + ki, 4 + ki};
                    const double wg = w * transform_.slope(f);
                    const std::array<double, 3> value = {-wg * p[4 + ki] * d_lobe, -wg / kPi, -wg * l};
                    for (size_t x = 0; x < 3; ++x) {
                        part.jtr[column[x]] += value[x] * r;
                        for (size_t y = 0; y < 3; ++y) part.jtj(column[x], column[y]) += value[x] * value[y];
                    }
                }
            }
            return part;
        });
    }

    double cost(const Eigen::VectorXd& p) const { return accumulate(p, false).cost; }

    double normal_equations(const Eigen::VectorXd& p, Eigen::MatrixXd& jtj, Eigen::VectorXd& jtr) const {
        const Normal n = accumulate(p, true);
        jtj = n.jtj;
        jtr = n.jtr;
        return n.cost;
    }

private:
    const std::vector<Observation>& samples_;
    Transform transform_;
    std::vector<double> log_n_dot_h_, geometry_;
};

const char* kChannel[] = {"red", "green", "blue"};

// The global optimum of the linear problem; with `polish_transform` set, the polish minimises the
// compressed residual instead, starting from `start` (the reweighted solution) when given.
void run_global(const std::vector<Observation>& samples, const FitOptions& options, FitResult& result,
                const Transform& polish_transform = {}, const FitResult* start = nullptr) {
    const GlobalFit linear(samples);
    const GlobalFit compressed(samples, polish_transform);
    const GlobalFit& problem = polish_transform.kind == Residual::Linear ? linear : compressed;
    Eigen::VectorXd p(7), lower(7), upper(7);
    if (start) {
        p << std::log(start->ns), start->cd[0], start->cd[1], start->cd[2], start->cs[0], start->cs[1], start->cs[2];
    } else {
        const double ns = linear.search_exponent(options.on_progress);
        const GlobalFit::Scales scales = linear.best_scales(ns);
        p << std::log(ns), scales.cd[0], scales.cd[1], scales.cd[2], scales.cs[0], scales.cs[1], scales.cs[2];
    }
    lower << std::log(kMinExponent), 0, 0, 0, 0, 0, 0;
    upper << std::log(kMaxExponent), 1e300, 1e300, 1e300, 1, 1, 1;
    std::function<void(const Eigen::VectorXd&, double)> after_iteration;
    int iteration = 0;
    if (options.on_progress)
        after_iteration = [&](const Eigen::VectorXd& now, double cost) {
            const double expected = 30;  // polishes take a few to ~20 iterations here
            options.on_progress({0.6 + 0.4 * std::min(++iteration / expected, 1.0), "polish",
                                 std::exp(now[0]), {now[1], now[2], now[3]}, {now[4], now[5], now[6]}, cost});
        };
    const BoundedReport polish = bounded_levenberg_marquardt(problem, p, lower, upper, {}, after_iteration);
    result.ns = std::exp(p[0]);
    for (size_t k = 0; k < 3; ++k) {
        result.cd[k] = p[static_cast<Eigen::Index>(1 + k)];
        result.cs[k] = p[static_cast<Eigen::Index>(4 + k)];
    }
    result.solver = "global";
    result.stop_reason = std::string("polish: ") + stop_reason_text(polish.reason) + " after " + std::to_string(polish.iterations) +
                         " iterations";
    result.converged = polish.converged();
    if (!result.converged) result.warnings.push_back("the polish did not converge: " + std::string(stop_reason_text(polish.reason)));
    if (polish.at_lower[0] || polish.at_upper[0])
        result.warnings.push_back("ns is at the end of its search range (" + std::to_string(result.ns) +
                                  "): the data have no lobe this model can describe");
    for (size_t k = 0; k < 3; ++k) {
        if (polish.at_lower[1 + k]) result.warnings.push_back(std::string("cd (") + kChannel[k] + ") is at its bound 0");
        if (polish.at_lower[4 + k]) result.warnings.push_back(std::string("cs (") + kChannel[k] + ") is at its bound 0: no specular lobe");
        if (polish.at_upper[4 + k])
            result.warnings.push_back(std::string("cs (") + kChannel[k] + ") is at its bound 1: the renderer form's Rs = 1 leaves no diffuse part");
    }
    for (const double cost : polish.cost_per_iteration) result.error_per_iteration.push_back(std::sqrt(cost));
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
        const double e = std::sqrt(error_number(samples, -1, now[0], now[1], now[2]));
        result.error_per_iteration.push_back(e);
        if (options.on_progress)
            options.on_progress({static_cast<double>(result.error_per_iteration.size()) / options.iterations, "stage 1", now[0],
                                 {now[1], now[1], now[1]}, {now[2], now[2], now[2]}, e * e});
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
    if (options.solver == Solver::Thesis && (options.residual != Residual::Linear || options.loss != Loss::Squared))
        throw UsageError("fit: the thesis solver fits the linear residual by least squares only (use the global solver)");
}

Observations observations(const BrdfGrid& grid, double limit_deg) {
    const std::vector<double> w = solid_angle_weights(grid, limit_deg);
    double sum = 0;
    for (double x : w) sum += x;
    Observations data;
    data.total = grid.size();
    for (size_t i = 0; i < grid.theta_in.size(); ++i) {
        const glm::dvec3 l = grid.light(i);
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p) {
                const double weight = w[o * grid.phi_out.size() + p];
                // Light at the horizon: weight cos θi = 0, and the lobe's max(n·l, n·v) may be 0 too (0 · ∞).
                if (grid.theta_in[i] > limit_deg || l.z < 1e-9 || weight <= 0) {
                    ++data.outside_limit;
                    continue;
                }
                data.samples.push_back({l, grid.camera(o, p), weight * l.z / sum, grid.values[grid.index(i, o, p)]});
            }
    }
    return data;
}

Observations observations(const MerlBrdf& merl, double limit_deg) {
    // Every bin at its centre: θh = ((h + ½)/90)² · 90° (the table's square-root index), θd and φd
    // linear, φh = 0 (isotropic). Its measure in (ωi, ωo) is 4 cos θd sin θh sin θd dθh dθd dφd
    // (Rusinkiewicz's Jacobian, dφh integrated); times cos θi as in eq. 4.25.
    const double limit_cos = std::cos(limit_deg * kPi / 180.0) - 1e-12;
    Observations data;
    data.total = static_cast<size_t>(kMerlThetaH) * kMerlThetaD * kMerlPhiD;
    data.samples.reserve(data.total);
    double sum = 0;
    for (int h = 0; h < kMerlThetaH; ++h) {
        const double d_theta_h = (2.0 * h + 1.0) / (kMerlThetaH * kMerlThetaH) * kPi / 2;
        for (int d = 0; d < kMerlThetaD; ++d)
            for (int p = 0; p < kMerlPhiD; ++p) {
                const BinDirections b = merl_bin_centre(h, d, p);
                const std::array<double, 3> value = merl.bin(h, d, p);
                if (value[0] < 0 || value[1] < 0 || value[2] < 0) {
                    ++data.masked;
                    continue;
                }
                if (b.l.z < limit_cos || b.v.z < limit_cos || b.l.z < 1e-9 || b.v.z < 1e-9) {
                    ++data.outside_limit;
                    continue;
                }
                const double measure = 4.0 * std::cos(b.theta_diff) * std::sin(b.theta_half) * std::sin(b.theta_diff) * d_theta_h *
                                       (kPi / 2 / kMerlThetaD) * (kPi / kMerlPhiD);
                sum += measure * b.l.z;
                data.samples.push_back({b.l, b.v, measure * b.l.z, value});
            }
    }
    // The weights sum to 1: a cost does not grow with the number of bins.
    for (Observation& o : data.samples) o.weight /= sum;
    return data;
}

FitResult fit_ashikhmin_shirley(const BrdfGrid& measured, const FitOptions& options) {
    validate(options);
    return fit_ashikhmin_shirley(observations(measured, options.limit_deg), options);
}

namespace {

double model_value(const Observation& s, const FitResult& fit, size_t c) {
    return fit.cd[c] / kPi + fit.cs[c] * ashikhmin_lobe(s.l, s.v, fit.ns);
}

// The robust weight ω(r) of a residual r at scale δ: ψ(r)/r of the loss.
double robust_weight(Loss loss, double r, double scale) {
    const double t = std::abs(r) / scale;
    if (loss == Loss::Huber) return t <= 1 ? 1.0 : 1.0 / t;
    if (loss == Loss::Cauchy) return 1.0 / (1.0 + t * t);
    return 1.0;
}

const char* residual_name(Residual r) { return r == Residual::CubeRoot ? "cube root" : r == Residual::Log ? "log" : "linear"; }
const char* loss_name(Loss l) { return l == Loss::Huber ? "Huber" : l == Loss::Cauchy ? "Cauchy" : "squared"; }

// A compressed residual and/or a robust loss. The exponent is searched globally on the linear
// residual; from that optimum a bounded Levenberg-Marquardt minimises Σ (w_j (g(y) − g(f)))² itself
// (a local step: the compressed problem has no linear structure to search globally). A robust loss is
// iteratively reweighted least squares: each round sets ω_j from the current residuals and solves
// again with weights w_j ω_j^½, until no parameter moves by more than 1e-5 of itself.
void run_reweighted(const std::vector<Observation>& samples, const FitOptions& options, FitResult& result) {
    double mean = 0;
    for (const Observation& s : samples) mean += (s.value[0] + s.value[1] + s.value[2]) / 3.0;
    mean /= static_cast<double>(samples.size());
    const Transform transform{options.residual, 1e-3 * std::max(mean, 1e-12)};
    const std::vector<std::string> warnings = result.warnings;
    run_global(samples, options, result);  // the linear least-squares optimum: the start
    std::vector<std::string> round_warnings = result.warnings;
    std::vector<Observation> robust = samples;
    double scale = options.loss_scale;
    bool settled = false;
    const int rounds = options.loss == Loss::Squared ? 1 : 300;  // the reweighting converges linearly: Cauchy on poorly fitting data needs ~200
    for (int round = 1; round <= rounds && !settled; ++round) {
        if (options.loss != Loss::Squared) {
            std::vector<double> residuals(samples.size());
            for (size_t j = 0; j < samples.size(); ++j) {
                double sum = 0;
                for (size_t c = 0; c < 3; ++c) {
                    const double r = transform.value(samples[j].value[c]) - transform.value(model_value(samples[j], result, c));
                    sum += r * r;
                }
                residuals[j] = samples[j].weight * std::sqrt(sum / 3.0);
            }
            if (!(scale > 0)) {  // Huber's 1.345 σ, σ from the median absolute residual of the start
                std::vector<double> sorted = residuals;
                std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
                scale = 1.345 * 1.4826 * std::max(sorted[sorted.size() / 2], 1e-300);
            }
            for (size_t j = 0; j < samples.size(); ++j)
                robust[j].weight = samples[j].weight * std::sqrt(robust_weight(options.loss, residuals[j], scale));
        }
        FitResult next;
        const FitResult current = result;
        run_global(robust, FitOptions{}, next, transform, &current);
        bool still = std::abs(next.ns - result.ns) <= 1e-5 * result.ns;
        for (size_t c = 0; c < 3; ++c)
            still = still && std::abs(next.cd[c] - result.cd[c]) <= 1e-8 + 1e-5 * result.cd[c] &&
                    std::abs(next.cs[c] - result.cs[c]) <= 1e-8 + 1e-5 * result.cs[c];
        settled = options.loss == Loss::Squared || still;  // least squares: one solve, nothing to reweight
        result.ns = next.ns;
        result.cd = next.cd;
        result.cs = next.cs;
        result.stop_reason = next.stop_reason;
        result.converged = next.converged;
        round_warnings = next.warnings;
        result.reweightings = options.loss == Loss::Squared ? 0 : round;
        if (options.on_progress) options.on_progress({std::min(0.6 + 0.004 * round, 0.99), "reweighting", result.ns, result.cd, result.cs, 0.0});
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
    result.cost = 0;
    for (size_t j = 0; j < samples.size(); ++j)
        for (size_t c = 0; c < 3; ++c) {
            const double r = robust[j].weight * (transform.value(samples[j].value[c]) - transform.value(model_value(samples[j], result, c)));
            result.cost += r * r;
        }
}

}  // namespace

FitResult fit_ashikhmin_shirley(const Observations& data, const FitOptions& options) {
    validate(options);
    const std::vector<Observation>& samples = data.samples;
    if (samples.size() < 3) throw Error("fit: fewer than 3 samples inside the limit angle");

    FitResult result;
    result.samples_used = static_cast<int>(samples.size());
    result.samples_masked = data.masked;
    if (data.masked > 0)
        result.warnings.push_back(std::to_string(data.masked) + " of " + std::to_string(data.total) +
                                  " samples are unmeasured (negative) and left out");
    const bool reweighted = options.solver == Solver::Global && (options.residual != Residual::Linear || options.loss != Loss::Squared);
    if (reweighted) {
        run_reweighted(samples, options, result);
        result.mono_cd = (result.cd[0] + result.cd[1] + result.cd[2]) / 3.0;
        result.mono_cs = (result.cs[0] + result.cs[1] + result.cs[2]) / 3.0;
    } else if (options.solver == Solver::Global) {
        run_global(samples, options, result);
        result.mono_cd = (result.cd[0] + result.cd[1] + result.cd[2]) / 3.0;
        result.mono_cs = (result.cs[0] + result.cs[1] + result.cs[2]) / 3.0;
    } else {
        run_thesis(samples, options, result);
    }
    result.error_mono = std::sqrt(error_number(samples, -1, result.ns, result.mono_cd, result.mono_cs));
    double rgb_sum = 0;
    for (int c = 0; c < 3; ++c)
        rgb_sum += error_number(samples, c, result.ns, result.cd[static_cast<size_t>(c)], result.cs[static_cast<size_t>(c)]);
    result.error_rgb = std::sqrt(rgb_sum);
    if (!reweighted) result.cost = weighted_cost(samples, result.ns, result.cd, result.cs);
    if (options.solver == Solver::Global) {
        result.optimum_cost = result.cost;
    } else {
        // What the thesis' schedule reached, against the global optimum of the same problem.
        FitResult best;
        run_global(samples, FitOptions{}, best);  // quietly: the reference optimum
        result.optimum_cost = weighted_cost(samples, best.ns, best.cd, best.cs);
        if (result.cost > 1.001 * result.optimum_cost + 1e-300) {
            result.converged = false;
            char text[256];
            std::snprintf(text, sizeof text,
                          "the thesis' schedule stopped at a weighted cost %.3gx the optimum (the default solver finds ns %.4g)",
                          result.cost / std::max(result.optimum_cost, 1e-300), best.ns);
            result.warnings.push_back(text);
        }
    }

    result.rs = std::max({result.cs[0], result.cs[1], result.cs[2]});
    if (result.rs >= 1) result.warnings.push_back("Rs = max(cs) >= 1: the renderer form (eq. 4.23) has no diffuse part");
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
