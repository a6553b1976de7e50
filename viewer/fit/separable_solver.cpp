#include "fit/separable_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"

namespace fxview::fit {

double ResidualTransform::value(double x) const {
    switch (kind) {
        case Residual::CubeRoot: return std::cbrt(x + epsilon);
        case Residual::Log: return std::log(std::max(x, 0.0) + epsilon);
        default: return x;
    }
}

double ResidualTransform::slope(double x) const {
    switch (kind) {
        case Residual::CubeRoot: return 1.0 / (3.0 * std::pow(std::cbrt(x + epsilon), 2.0));
        case Residual::Log: return 1.0 / (std::max(x, 0.0) + epsilon);
        default: return 1.0;
    }
}

namespace {

constexpr double kHuge = 1e300;  // "no upper bound" for the box solver
constexpr int kMaxShape = 2;

// Σ over the samples of the per-channel quadratic's coefficients:
// q(a, b) = yy − 2 a ya − 2 b yb + aa a² + 2 ab a b + bb b², y the data less the model's offset.
struct Moments {
    double aa = 0, ab = 0, bb = 0;
    std::array<double, 3> ya{}, yb{}, yy{};
    Moments& operator+=(const Moments& o) {
        aa += o.aa;
        ab += o.ab;
        bb += o.bb;
        for (size_t k = 0; k < 3; ++k) {
            ya[k] += o.ya[k];
            yb[k] += o.yb[k];
            yy[k] += o.yy[k];
        }
        return *this;
    }
};

struct Scales {
    std::array<double, 3> a{}, b{};
    double cost = 0;
};

class Problem {
public:
    Problem(const FitModel& model, const FitData& data, ResidualTransform transform)
        : model_(model), data_(data), transform_(transform), shape_count_(static_cast<int>(model.shape().size())),
          b_upper_(std::min(model.specular_upper(), kHuge)) {}

    int shape_count() const { return shape_count_; }
    int parameter_count() const { return shape_count_ + 6; }

    // The exact best scales for shape θ over every `stride`-th sample: per channel min of q over
    // a >= 0, 0 <= b <= b_upper. q is convex: the unconstrained optimum if feasible, else the best of
    // the edges' own minima.
    Scales best_scales(const double* shape, size_t stride = 1) const {
        const size_t count = (data_.geometry.size() + stride - 1) / stride;
        const Moments m = parallel_sum<Moments>(count, [&](size_t begin, size_t end) {
            Moments part;
            for (size_t i = begin; i < end; ++i) {
                const size_t j = i * stride;
                const Basis f = model_.basis(data_.geometry[j], shape);
                const double w2 = data_.weights[j] * data_.weights[j];
                part.aa += w2 * f.diffuse * f.diffuse;
                part.ab += w2 * f.diffuse * f.specular;
                part.bb += w2 * f.specular * f.specular;
                for (size_t k = 0; k < 3; ++k) {
                    const double y = data_.values[j][k] - f.offset;
                    part.ya[k] += w2 * y * f.diffuse;
                    part.yb[k] += w2 * y * f.specular;
                    part.yy[k] += w2 * y * y;
                }
            }
            return part;
        });
        Scales out;
        for (size_t k = 0; k < 3; ++k) {
            const auto q = [&](double a, double b) {
                return m.yy[k] - 2 * a * m.ya[k] - 2 * b * m.yb[k] + m.aa * a * a + 2 * m.ab * a * b + m.bb * b * b;
            };
            double best = q(0, 0), best_a = 0, best_b = 0;
            const auto consider = [&](double a, double b) {
                if (!(a >= 0 && b >= 0 && b <= b_upper_)) return;
                const double value = q(a, b);
                if (value < best) {
                    best = value;
                    best_a = a;
                    best_b = b;
                }
            };
            const double det = m.aa * m.bb - m.ab * m.ab;
            if (det > 1e-14 * m.aa * m.bb) consider((m.ya[k] * m.bb - m.yb[k] * m.ab) / det, (m.yb[k] * m.aa - m.ya[k] * m.ab) / det);
            if (m.bb > 0) consider(0, std::clamp(m.yb[k] / m.bb, 0.0, b_upper_));
            if (m.aa > 0) consider(std::max(m.ya[k] / m.aa, 0.0), 0);
            if (m.aa > 0 && b_upper_ < kHuge) consider(std::max((m.ya[k] - m.ab * b_upper_) / m.aa, 0.0), b_upper_);
            out.a[k] = best_a;
            out.b[k] = best_b;
            out.cost += best;
        }
        if (!std::isfinite(out.cost)) out.cost = std::numeric_limits<double>::infinity();
        return out;
    }

    // The polish's parameters p = (ln θ, a r g b, b r g b); residuals w (g(y) − g(f)) for every sample
    // and channel, handed over as normal equations (a Jacobian of 3 × 1.1 million rows would not fit).
    struct Normal {
        double cost = 0;
        Eigen::Matrix<double, 8, 8> jtj = Eigen::Matrix<double, 8, 8>::Zero();
        Eigen::Matrix<double, 8, 1> jtr = Eigen::Matrix<double, 8, 1>::Zero();
        Normal& operator+=(const Normal& o) {
            cost += o.cost;
            jtj += o.jtj;
            jtr += o.jtr;
            return *this;
        }
    };

    Normal accumulate(const Eigen::VectorXd& p, bool derivatives) const {
        double shape[kMaxShape] = {};
        for (int k = 0; k < shape_count_; ++k) shape[k] = std::exp(p[k]);
        const int K = shape_count_;
        return parallel_sum<Normal>(data_.geometry.size(), [&](size_t begin, size_t end) {
            Normal part;
            Basis d[kMaxShape];
            for (size_t j = begin; j < end; ++j) {
                const Basis f = model_.basis(data_.geometry[j], shape, derivatives ? d : nullptr);
                const double w = data_.weights[j];
                for (int c = 0; c < 3; ++c) {
                    const double a = p[K + c], b = p[K + 3 + c];
                    const double value = a * f.diffuse + b * f.specular + f.offset;
                    const double r = w * (transform_.value(data_.values[j][static_cast<size_t>(c)]) - transform_.value(value));
                    part.cost += r * r;
                    if (!derivatives) continue;
                    // The row's non-zeros: ∂r/∂ln θ_k, ∂r/∂a_c, ∂r/∂b_c.
                    const double wg = w * transform_.slope(value);
                    int column[kMaxShape + 2];
                    double entry[kMaxShape + 2];
                    int n = 0;
                    for (int k = 0; k < K; ++k, ++n) {
                        column[n] = k;
                        entry[n] = -wg * (a * d[k].diffuse + b * d[k].specular + d[k].offset);
                    }
                    column[n] = K + c;
                    entry[n++] = -wg * f.diffuse;
                    column[n] = K + 3 + c;
                    entry[n++] = -wg * f.specular;
                    for (int x = 0; x < n; ++x) {
                        part.jtr[column[x]] += entry[x] * r;
                        for (int y = 0; y < n; ++y) part.jtj(column[x], column[y]) += entry[x] * entry[y];
                    }
                }
            }
            return part;
        });
    }

    double cost(const Eigen::VectorXd& p) const { return accumulate(p, false).cost; }

    double normal_equations(const Eigen::VectorXd& p, Eigen::MatrixXd& jtj, Eigen::VectorXd& jtr) const {
        const Normal n = accumulate(p, true);
        const int P = parameter_count();
        jtj = n.jtj.topLeftCorner(P, P);
        jtr = n.jtr.head(P);
        return n.cost;
    }

    double b_upper() const { return b_upper_; }

private:
    const FitModel& model_;
    const FitData& data_;
    ResidualTransform transform_;
    int shape_count_;
    double b_upper_;
};

// Where the profile cost is lowest: a log-spaced grid over the whole range, then a compass search
// (steps halved down to 1e-7 in ln θ) from each of the best three local minima of the grid. Returns
// the refined minima (shapes), best first by the searched samples' profile cost (large data are
// searched on an evenly strided subset).
std::vector<std::vector<double>> search_shapes(const Problem& problem, const std::vector<ShapeParameter>& parameters, size_t sample_count,
                                               const SeparableProgress& progress) {
    const int K = static_cast<int>(parameters.size());
    const size_t stride = std::max<size_t>(1, sample_count / (K == 1 ? 100000 : 20000));
    const double per_decade = K == 1 ? 20.0 : 5.0;
    std::array<int, kMaxShape> points{1, 1};
    std::array<double, kMaxShape> low{}, high{};
    for (int k = 0; k < K; ++k) {
        low[k] = std::log(parameters[k].low);
        high[k] = std::log(parameters[k].high);
        points[k] = static_cast<int>(std::round(per_decade * std::log10(parameters[k].high / parameters[k].low))) + 1;
    }
    const auto at = [&](int k, int i) { return points[k] == 1 ? low[k] : low[k] + (high[k] - low[k]) * i / (points[k] - 1); };
    const auto profile = [&](const double* log_shape) {
        double shape[kMaxShape];
        for (int k = 0; k < K; ++k) shape[k] = std::exp(log_shape[k]);
        return problem.best_scales(shape, stride).cost;
    };
    const int total = points[0] * points[1];
    std::vector<double> grid(static_cast<size_t>(total));
    for (int i = 0; i < total; ++i) {
        const double x[kMaxShape] = {at(0, i % points[0]), at(1, i / points[0])};
        grid[static_cast<size_t>(i)] = profile(x);
        if (progress && i % 16 == 0) {
            const auto best = static_cast<size_t>(std::min_element(grid.begin(), grid.begin() + i + 1) - grid.begin());
            std::vector<double> shape(static_cast<size_t>(K));
            for (int k = 0; k < K; ++k) shape[static_cast<size_t>(k)] = std::exp(at(k, k == 0 ? static_cast<int>(best) % points[0] : static_cast<int>(best) / points[0]));
            const Scales s = problem.best_scales(shape.data(), stride);
            progress(0.5 * i / total, "search", shape, s.a, s.b, grid[best]);
        }
    }
    // Local minima of the grid (no neighbour lower), best first.
    std::vector<int> minima;
    for (int i = 0; i < total; ++i) {
        const int x = i % points[0], y = i / points[0];
        bool lowest = std::isfinite(grid[static_cast<size_t>(i)]);
        for (int dy = -1; dy <= 1 && lowest; ++dy)
            for (int dx = -1; dx <= 1 && lowest; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= points[0] || ny >= points[1]) continue;
                if (grid[static_cast<size_t>(ny * points[0] + nx)] < grid[static_cast<size_t>(i)]) lowest = false;
            }
        if (lowest) minima.push_back(i);
    }
    if (minima.empty()) minima.push_back(0);  // every profile cost infinite: nothing better to start from
    std::sort(minima.begin(), minima.end(), [&](int p, int q) { return grid[static_cast<size_t>(p)] < grid[static_cast<size_t>(q)]; });
    minima.resize(std::min<size_t>(minima.size(), 3));

    std::vector<std::pair<double, std::vector<double>>> refined;  // (cost, shape)
    for (const int start : minima) {
        double x[kMaxShape] = {at(0, start % points[0]), at(1, start / points[0])};
        double cost = profile(x);
        double step = points[0] > 1 ? (high[0] - low[0]) / (points[0] - 1) : 1.0;  // one grid spacing
        while (step > 1e-7) {
            bool moved = false;
            for (int k = 0; k < K; ++k)
                for (const double sign : {-1.0, 1.0}) {
                    double y[kMaxShape] = {x[0], x[1]};
                    y[k] = std::clamp(x[k] + sign * step, low[k], high[k]);
                    if (y[k] == x[k]) continue;
                    const double c = profile(y);
                    if (c < cost) {
                        cost = c;
                        x[k] = y[k];
                        moved = true;
                    }
                }
            if (!moved) step *= 0.5;
        }
        std::vector<double> shape(x, x + K);
        for (double& v : shape) v = std::exp(v);
        refined.emplace_back(cost, std::move(shape));
    }
    std::stable_sort(refined.begin(), refined.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
    std::vector<std::vector<double>> shapes;
    for (auto& r : refined) shapes.push_back(std::move(r.second));
    return shapes;
}

}  // namespace

namespace {

// The bounded Levenberg-Marquardt over every parameter and sample, from `s`.
SeparableSolution polish(const Problem& problem, const std::vector<ShapeParameter>& parameters, SeparableSolution s, const SeparableProgress& progress) {
    const int K = static_cast<int>(parameters.size());
    const int P = problem.parameter_count();
    Eigen::VectorXd p(P), lower(P), upper(P);
    for (int k = 0; k < K; ++k) {
        p[k] = std::log(std::clamp(s.shape[static_cast<size_t>(k)], parameters[static_cast<size_t>(k)].low, parameters[static_cast<size_t>(k)].high));
        lower[k] = std::log(parameters[static_cast<size_t>(k)].low);
        upper[k] = std::log(parameters[static_cast<size_t>(k)].high);
    }
    for (int c = 0; c < 3; ++c) {
        p[K + c] = s.a[static_cast<size_t>(c)];
        p[K + 3 + c] = std::min(s.b[static_cast<size_t>(c)], problem.b_upper());
        lower[K + c] = lower[K + 3 + c] = 0;
        upper[K + c] = kHuge;
        upper[K + 3 + c] = problem.b_upper();
    }
    std::function<void(const Eigen::VectorXd&, double)> after_iteration;
    int iteration = 0;
    std::vector<double> shape(static_cast<size_t>(K));
    if (progress)
        after_iteration = [&](const Eigen::VectorXd& now, double cost) {
            const double expected = 30;  // polishes take a few to ~20 iterations
            for (int k = 0; k < K; ++k) shape[static_cast<size_t>(k)] = std::exp(now[k]);
            progress(0.5 + 0.5 * std::min(++iteration / expected, 1.0), "polish", shape, {now[K], now[K + 1], now[K + 2]},
                     {now[K + 3], now[K + 4], now[K + 5]}, cost);
        };
    s.polish = bounded_levenberg_marquardt(problem, p, lower, upper, {}, after_iteration);
    s.shape.assign(static_cast<size_t>(K), 0.0);
    for (int k = 0; k < K; ++k) s.shape[static_cast<size_t>(k)] = std::exp(p[k]);
    for (int c = 0; c < 3; ++c) {
        s.a[static_cast<size_t>(c)] = p[K + c];
        s.b[static_cast<size_t>(c)] = p[K + 3 + c];
    }
    s.cost = s.polish.cost;
    return s;
}

// Minima whose profile cost over all samples is within this share of the best one's are all
// polished: a subset's ranking (or the polish itself) can swap such near-ties (a MERL file's two
// minima 0.35 % apart once ended at the worse one).
constexpr double kNearTie = 0.02;

}  // namespace

SeparableSolution solve_separable(const FitModel& model, const FitData& data, const ResidualTransform& transform,
                                  const SeparableSolution* start, const SeparableProgress& progress) {
    const std::vector<ShapeParameter> parameters = model.shape();
    const Problem linear(model, data, ResidualTransform{});
    const Problem transformed(model, data, transform);
    const Problem& problem = transform.kind == Residual::Linear ? linear : transformed;
    if (start) return polish(problem, parameters, *start, progress);
    const std::vector<std::vector<double>> shapes = search_shapes(linear, parameters, data.geometry.size(), progress);
    // Each refined minimum with its exact scales over all samples, best first.
    std::vector<SeparableSolution> starts;
    for (const std::vector<double>& shape : shapes) {
        SeparableSolution s;
        s.shape = shape;
        const Scales scales = linear.best_scales(shape.data());
        s.a = scales.a;
        s.b = scales.b;
        s.cost = scales.cost;
        starts.push_back(std::move(s));
    }
    std::stable_sort(starts.begin(), starts.end(), [](const SeparableSolution& p, const SeparableSolution& q) { return p.cost < q.cost; });
    SeparableSolution best;
    best.cost = std::numeric_limits<double>::infinity();
    for (const SeparableSolution& s : starts) {
        if (!(s.cost <= starts.front().cost * (1.0 + kNearTie)) && std::isfinite(best.cost)) break;
        SeparableSolution polished = polish(problem, parameters, s, progress);
        if (!(polished.cost >= best.cost)) best = std::move(polished);
    }
    return best;
}

double separable_cost(const FitModel& model, const FitData& data, const ResidualTransform& transform, const std::vector<double>& shape,
                      const std::array<double, 3>& a, const std::array<double, 3>& b) {
    const Problem problem(model, data, transform);
    const int K = problem.shape_count();
    Eigen::VectorXd p(problem.parameter_count());
    for (int k = 0; k < K; ++k) p[k] = std::log(shape[static_cast<size_t>(k)]);
    for (int c = 0; c < 3; ++c) {
        p[K + c] = a[static_cast<size_t>(c)];
        p[K + 3 + c] = b[static_cast<size_t>(c)];
    }
    return problem.cost(p);
}

}  // namespace fxview::fit
