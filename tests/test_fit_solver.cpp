// The fitter's solvers: the bounded Levenberg-Marquardt core against NIST's certified results
// (Statistical Reference Datasets, nonlinear regression), and the default solver against an
// independent global optimum of the same weighted least-squares problem on data of other models.
#include <doctest/doctest.h>

#include <Eigen/QR>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "brdf/microfacet.hpp"
#include "brdf/models.hpp"
#include "core/error.hpp"
#include "fit/brdf_fit.hpp"
#include "fit/bounded_levenberg_marquardt.hpp"
#include "fit/brdf_grid.hpp"
#include "fit/fit_model.hpp"
#include "fit/separable_solver.hpp"

using namespace fxview;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// y = model(x, b), residuals y_i − model, Jacobian by central differences (the core must not need
// analytic derivatives to reach the certified values).
template <typename Model>
struct CurveFit {
    std::vector<double> x, y;
    Model model;

    void residuals(const Eigen::VectorXd& b, Eigen::VectorXd& r) const {
        r.resize(static_cast<Eigen::Index>(x.size()));
        for (size_t i = 0; i < x.size(); ++i) r[static_cast<Eigen::Index>(i)] = y[i] - model(x[i], b);
    }
    void jacobian(const Eigen::VectorXd& b, Eigen::MatrixXd& d) const {
        d.resize(static_cast<Eigen::Index>(x.size()), b.size());
        for (Eigen::Index k = 0; k < b.size(); ++k) {
            const double h = 1e-7 * std::max(std::abs(b[k]), 1e-3);
            Eigen::VectorXd up = b, down = b;
            up[k] += h;
            down[k] -= h;
            for (size_t i = 0; i < x.size(); ++i) d(static_cast<Eigen::Index>(i), k) = -(model(x[i], up) - model(x[i], down)) / (2 * h);
        }
    }
};

template <typename Model>
void check_certified(const CurveFit<Model>& problem, Eigen::VectorXd start, const std::vector<double>& certified, double certified_rss) {
    const Eigen::VectorXd lower = Eigen::VectorXd::Constant(start.size(), -kInf), upper = Eigen::VectorXd::Constant(start.size(), kInf);
    const fit::BoundedReport report = fit::bounded_levenberg_marquardt(problem, start, lower, upper, {.max_iterations = 1000});
    CHECK(report.converged());
    // NIST asks for agreement to about 6 significant digits with the certified values, which were
    // computed in 128-bit arithmetic; the residual sum of squares then agrees to ~1e-10.
    for (size_t k = 0; k < certified.size(); ++k) CHECK(start[static_cast<Eigen::Index>(k)] == doctest::Approx(certified[k]).epsilon(1e-6));
    CHECK(report.cost == doctest::Approx(certified_rss).epsilon(1e-9));
}

}  // namespace

TEST_CASE("bounded Levenberg-Marquardt reaches NIST's certified values (Misra1a, BoxBOD, MGH09)") {
    const auto exponential = [](double x, const Eigen::VectorXd& b) { return b[0] * (1.0 - std::exp(-b[1] * x)); };
    // Misra1a (lower difficulty), start 1.
    const CurveFit<decltype(exponential)> misra{{77.6, 114.9, 141.1, 190.8, 239.9, 289.0, 332.8, 378.4, 434.8, 477.3, 536.8, 593.1, 689.1, 760.0},
                                                {10.07, 14.73, 17.94, 23.93, 29.61, 35.18, 40.02, 44.82, 50.76, 55.05, 61.01, 66.40, 75.47, 81.78},
                                                exponential};
    check_certified(misra, Eigen::Vector2d(500, 1e-4), {2.3894212918E+02, 5.5015643181E-04}, 1.2455138894E-01);
    // BoxBOD (higher difficulty), start 2.
    const CurveFit<decltype(exponential)> boxbod{{1, 2, 3, 5, 7, 10}, {109, 149, 149, 191, 213, 224}, exponential};
    check_certified(boxbod, Eigen::Vector2d(100, 0.75), {2.1380940889E+02, 5.4723748542E-01}, 1.1680088766E+03);
    // MGH09, Kowalik and Osborne (higher difficulty), start 2.
    const auto rational = [](double x, const Eigen::VectorXd& b) { return b[0] * (x * x + x * b[1]) / (x * x + x * b[2] + b[3]); };
    const CurveFit<decltype(rational)> mgh09{{4, 2, 1, 0.5, 0.25, 0.167, 0.125, 0.1, 0.0833, 0.0714, 0.0625},
                                             {0.1957, 0.1947, 0.1735, 0.16, 0.0844, 0.0627, 0.0456, 0.0342, 0.0323, 0.0235, 0.0246},
                                             rational};
    check_certified(mgh09, Eigen::Vector4d(0.25, 0.39, 0.415, 0.39),
                    {1.9280693458E-01, 1.9128232873E-01, 1.2305650693E-01, 1.3606233068E-01}, 3.0750560385E-04);
}

TEST_CASE("bounded Levenberg-Marquardt stays in its box and says which bounds hold") {
    // Misra1a with b2 capped below its optimum: the fit ends on the cap, reported as such.
    const auto exponential = [](double x, const Eigen::VectorXd& b) { return b[0] * (1.0 - std::exp(-b[1] * x)); };
    const CurveFit<decltype(exponential)> misra{{77.6, 114.9, 141.1, 190.8, 239.9, 289.0, 332.8, 378.4, 434.8, 477.3, 536.8, 593.1, 689.1, 760.0},
                                                {10.07, 14.73, 17.94, 23.93, 29.61, 35.18, 40.02, 44.82, 50.76, 55.05, 61.01, 66.40, 75.47, 81.78},
                                                exponential};
    Eigen::VectorXd b = Eigen::Vector2d(500, 1e-4);
    const fit::BoundedReport report =
        fit::bounded_levenberg_marquardt(misra, b, Eigen::Vector2d(0, 0), Eigen::Vector2d(kInf, 4e-4), {.max_iterations = 1000});
    CHECK(report.converged());
    CHECK(b[1] == 4e-4);
    CHECK(report.at_upper[1]);
    CHECK(!report.at_upper[0]);
    CHECK(!report.at_lower[0]);
}

namespace {

// A model as the renderer's CPU reference evaluates it (viewer/brdf/models.cpp, not the fitter's
// basis), with scales a and b (the same in every channel) and one shape parameter.
using RendererModel = std::function<double(const brdf::Directions& d, double a, double b, double shape)>;

RendererModel thesis_model() {
    return [](const brdf::Directions& d, double a, double b, double ns) {
        return brdf::evaluate(brdf::AshikhminShirleyFit{glm::dvec3(a), glm::dvec3(b), ns}, d).r;
    };
}

// The weighted cost of eq. 4.27 with the best bounded scales (a >= 0, 0 <= b <= b_upper) at each
// shape, computed here from its definition: the model's columns from the renderer's model
// (f(a, b) = a·diffuse + b·specular + offset), Eigen's QR and the box's edges; minimised over the
// shape by a dense scan (50 points per decade) refined by golden-section search: an optimum found
// without the fitter's code.
double independent_optimum(const fit::BrdfGrid& grid, double limit_deg, const RendererModel& model = thesis_model(), double low = 1e-2,
                           double high = 1e6, double b_upper = 1.0) {
    const std::vector<double> w = fit::solid_angle_weights(grid, limit_deg);
    double sum = 0;
    for (double x : w) sum += x;
    std::vector<double> weight;
    std::vector<glm::dvec3> lights, views;
    std::vector<std::array<double, 3>> values;
    for (size_t i = 0; i < grid.theta_in.size(); ++i) {
        const glm::dvec3 l = grid.light(i);
        if (grid.theta_in[i] > limit_deg || l.z < 1e-9) continue;
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p) {
                const double wo = w[o * grid.phi_out.size() + p];
                if (wo <= 0) continue;
                weight.push_back(wo * l.z / sum);
                lights.push_back(l);
                views.push_back(grid.camera(o, p));
                values.push_back(grid.values[grid.index(i, o, p)]);
            }
    }
    const auto n = static_cast<Eigen::Index>(weight.size());
    const auto cost_at = [&](double log_shape) {
        const double shape = std::exp(log_shape);
        Eigen::MatrixXd design(n, 2);
        Eigen::VectorXd offset(n);
        for (Eigen::Index j = 0; j < n; ++j) {
            const auto k = static_cast<size_t>(j);
            const brdf::Directions d{{0, 0, 1}, lights[k], views[k], {1, 0, 0}};
            offset[j] = weight[k] * model(d, 0, 0, shape);
            design(j, 0) = weight[k] * model(d, 1, 0, shape) - offset[j];
            design(j, 1) = weight[k] * model(d, 0, 1, shape) - offset[j];
        }
        const auto qr = design.colPivHouseholderQr();
        const double top = std::min(b_upper, 1e300);
        double total = 0;
        for (size_t c = 0; c < 3; ++c) {
            Eigen::VectorXd target(n);
            for (Eigen::Index j = 0; j < n; ++j) target[j] = weight[static_cast<size_t>(j)] * values[static_cast<size_t>(j)][c] - offset[j];
            const Eigen::VectorXd x = qr.solve(target);
            const Eigen::VectorXd d = design.col(0), s = design.col(1);
            std::vector<Eigen::Vector2d> candidates = {{0, 0}, {0, std::clamp(s.dot(target) / s.dot(s), 0.0, top)},
                                                       {std::max(d.dot(target) / d.dot(d), 0.0), 0}};
            if (b_upper < kInf) candidates.push_back({std::max(d.dot(target - b_upper * s) / d.dot(d), 0.0), b_upper});
            if (x[0] >= 0 && x[1] >= 0 && x[1] <= b_upper) candidates.push_back(x);
            double best = kInf;
            for (const auto& cand : candidates) best = std::min(best, (target - design * cand).squaredNorm());
            total += best;
        }
        return total;
    };
    const double lo = std::log(low), hi = std::log(high);
    const int points = static_cast<int>(50 * std::log10(high / low));
    int best = 0;
    double best_cost = kInf;
    for (int i = 0; i <= points; ++i) {
        const double c = cost_at(lo + (hi - lo) * i / points);
        if (c < best_cost) {
            best_cost = c;
            best = i;
        }
    }
    double from = lo + (hi - lo) * std::max(best - 1, 0) / points, to = lo + (hi - lo) * std::min(best + 1, points) / points;
    for (int i = 0; i < 60; ++i) {
        const double p = to - 0.618034 * (to - from), q = from + 0.618034 * (to - from);
        if (cost_at(p) < cost_at(q)) to = q;
        else from = p;
    }
    return std::min(best_cost, cost_at(0.5 * (from + to)));
}

fit::BrdfGrid tabulate_model(const std::function<glm::dvec3(const brdf::Directions&)>& f) {
    return fit::tabulate(fit::thesis_grid(), [&](const glm::dvec3& l, const glm::dvec3& v) {
        const glm::dvec3 value = f({{0, 0, 1}, l, v, {1, 0, 0}});
        return std::array<double, 3>{value.r, value.g, value.b};
    });
}

}  // namespace

TEST_CASE("the default solver reaches the global optimum on other models' data, in bounds") {
    struct Case {
        std::string name;
        fit::BrdfGrid data;
        double limit;
    };
    std::vector<Case> cases;
    const brdf::MetallicRoughness gold{{0.9, 0.6, 0.3}, 1.0, 0.3}, dielectric{glm::dvec3(0.04), 0.0, 0.2};
    cases.push_back({"GGX metal", tabulate_model([&](const brdf::Directions& d) { return brdf::evaluate(gold, d); }), 75});
    // The stall of issue #11: the thesis' schedule stops at ns 58, the optimum lies near 1900.
    cases.push_back({"GGX dielectric", tabulate_model([&](const brdf::Directions& d) { return brdf::evaluate(dielectric, d); }), 75});
    const brdf::CookTorranceBeckmann beckmann{glm::dvec3(0.3, 0.2, 0.1), 0.5, 0.25, 1.5, false};
    cases.push_back({"Beckmann", tabulate_model([&](const brdf::Directions& d) { return brdf::evaluate(beckmann, d); }), 60});
    const brdf::AshikhminShirley fresnel{glm::dvec3(0.5, 0.4, 0.3), glm::dvec3(0.05), 300, 300};
    cases.push_back({"Ashikhmin-Shirley with Fresnel", tabulate_model([&](const brdf::Directions& d) { return brdf::evaluate(fresnel, d); }), 90});
    const brdf::ModifiedPhong low{glm::dvec3(0.6), 0.02, 30};
    cases.push_back({"low specular", tabulate_model([&](const brdf::Directions& d) { return brdf::evaluate(low, d); }), 45});
    fit::BrdfGrid noisy = cases.front().data;
    std::mt19937 random(7);
    std::normal_distribution<double> gauss(0.0, 1.0);
    for (auto& v : noisy.values)
        for (double& c : v) c *= 1.0 + 0.03 * gauss(random);
    for (size_t i = 0; i < noisy.values.size(); i += 997) noisy.values[i][1] *= 10.0;  // outliers
    cases.push_back({"noise and outliers", noisy, 75});

    for (const Case& c : cases) {
        CAPTURE(c.name);
        const fit::FitResult fit = fit::fit_brdf(c.data, {.limit_deg = c.limit});
        const double optimum = independent_optimum(c.data, c.limit);
        MESSAGE(c.name, ": ns ", fit.ns, ", cost ", fit.cost, " / independent optimum ", optimum, " (", fit.stop_reason, ")");
        CHECK(fit.converged);
        CHECK(fit.cost <= 1.001 * optimum);  // the bar: within 0.1 % of an independent optimum
        CHECK(fit.ns > 0);
        for (size_t k = 0; k < 3; ++k) {
            CHECK(fit.cd[k] >= 0);
            CHECK(fit.cs[k] >= 0);
            CHECK(fit.cs[k] <= 1);
        }
    }
}

TEST_CASE("the thesis' schedule is kept, and its stall is reported, never silent") {
    const brdf::MetallicRoughness dielectric{glm::dvec3(0.04), 0.0, 0.2};
    const fit::BrdfGrid data = tabulate_model([&](const brdf::Directions& d) { return brdf::evaluate(dielectric, d); });
    const fit::FitResult thesis = fit::fit_brdf(data, {.solver = fit::Solver::Thesis});
    CHECK(thesis.ns < 100);  // seed 000's solver from its start (25, 0.2, 0.2) stalls here
    CHECK(!thesis.converged);
    CHECK(thesis.cost > 5 * thesis.optimum_cost);
    CHECK(!thesis.warnings.empty());
    const fit::FitResult global = fit::fit_brdf(data, {});
    CHECK(global.ns == doctest::Approx(1933).epsilon(0.01));
    CHECK(global.cost == doctest::Approx(thesis.optimum_cost).epsilon(1e-9));
}

TEST_CASE("start values that are not numbers, or negative, are usage errors") {
    const fit::BrdfGrid data = fit::thesis_grid();
    for (const double bad : {std::nan(""), kInf, -3.0, 0.0}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(fit::validate({.start_ns = bad}), UsageError);
    }
    for (const double bad : {std::nan(""), -kInf, -0.1}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(fit::validate({.start_cd = bad}), UsageError);
        CHECK_THROWS_AS(fit::validate({.start_cs = bad}), UsageError);
    }
    CHECK_THROWS_AS(fit::validate({.limit_deg = std::nan("")}), UsageError);
    CHECK_NOTHROW(fit::validate({}));
}

namespace {

// The fit model's own data: the thesis' grid of eq. 4.28 with known parameters.
fit::BrdfGrid model_grid(double ns, const std::array<double, 3>& cd, const std::array<double, 3>& cs) {
    return fit::tabulate(fit::thesis_grid(), [&](const glm::dvec3& l, const glm::dvec3& v) {
        const double lobe = fit::ashikhmin_lobe(l, v, ns);
        return std::array<double, 3>{cd[0] / std::numbers::pi + cs[0] * lobe, cd[1] / std::numbers::pi + cs[1] * lobe,
                                     cd[2] / std::numbers::pi + cs[2] * lobe};
    });
}

}  // namespace

TEST_CASE("robust losses recover the model under outliers that pull least squares away") {
    const std::array<double, 3> cd{0.15, 0.30, 0.45}, cs{0.50, 0.40, 0.20};
    fit::BrdfGrid data = model_grid(120.0, cd, cs);
    // 2 % of the directions read 6x too high in every channel (a reflection in the goniometer).
    for (size_t i = 0; i < data.values.size(); i += 50)
        for (double& c : data.values[i]) c *= 6.0;
    const fit::FitResult squared = fit::fit_brdf(data, {});
    CHECK(std::abs(squared.cd[0] - cd[0]) > 0.05 * cd[0]);  // least squares is pulled off by > 5 %
    for (const fit::Loss loss : {fit::Loss::Huber, fit::Loss::Cauchy}) {
        fit::FitOptions options;
        options.loss = loss;
        const fit::FitResult robust = fit::fit_brdf(data, options);
        CAPTURE(robust.loss);
        CAPTURE(robust.stop_reason);
        CHECK(robust.converged);
        CHECK(robust.loss_scale_used > 0);
        // Huber keeps a bounded pull from each outlier (ψ = δ sign r), Cauchy almost none. Measured
        // here: Huber 0.37 %, Cauchy 0.015 % on cd (least squares 10 %); 1 % and 0.1 % bound them with margin.
        const double bound = loss == fit::Loss::Huber ? 0.01 : 0.001;
        MESSAGE(robust.loss, ": ns ", robust.ns, " cd ", robust.cd[0], " ", robust.cd[1], " ", robust.cd[2], " cs ", robust.cs[0], " ",
                robust.cs[1], " ", robust.cs[2], " (least squares: ns ", squared.ns, " cd ", squared.cd[0], ")");
        CHECK(robust.ns == doctest::Approx(120.0).epsilon(bound));
        for (size_t c = 0; c < 3; ++c) {
            CHECK(robust.cd[c] == doctest::Approx(cd[c]).epsilon(bound));
            CHECK(robust.cs[c] == doctest::Approx(cs[c]).epsilon(bound));
        }
    }
}

TEST_CASE("compressed residuals: exact data come back exactly; on other data the result is a minimum of the compressed cost") {
    const std::array<double, 3> cd{0.15, 0.30, 0.45}, cs{0.50, 0.40, 0.20};
    for (const fit::Residual residual : {fit::Residual::CubeRoot, fit::Residual::Log}) {
        fit::FitOptions options;
        options.residual = residual;
        const fit::FitResult exact = fit::fit_brdf(model_grid(120.0, cd, cs), options);
        CAPTURE(exact.residual);
        CHECK(exact.ns == doctest::Approx(120.0).epsilon(1e-6));  // any g: zero residual at the truth
        for (size_t c = 0; c < 3; ++c) CHECK(exact.cs[c] == doctest::Approx(cs[c]).epsilon(1e-6));
    }
    // GGX data (not the model's): the compressed cost, written here from its definition, is lowest at
    // the result: moving any parameter by 0.2 % raises it.
    const brdf::MetallicRoughness gold{{0.9, 0.6, 0.3}, 1.0, 0.3};
    const fit::BrdfGrid data = tabulate_model([&](const brdf::Directions& d) { return brdf::evaluate(gold, d); });
    fit::FitOptions options;
    options.residual = fit::Residual::CubeRoot;
    const fit::FitResult r = fit::fit_brdf(data, options);
    CHECK(r.converged);
    const fit::Observations obs = fit::observations(data, options.limit_deg);
    double mean = 0;
    for (const auto& s : obs.samples) mean += (s.value[0] + s.value[1] + s.value[2]) / 3.0;
    const double epsilon = 1e-3 * mean / static_cast<double>(obs.samples.size());
    const auto cost = [&](double ns, std::array<double, 3> d, std::array<double, 3> s) {
        double sum = 0;
        for (const auto& o : obs.samples) {
            const double lobe = fit::ashikhmin_lobe(o.l, o.v, ns);
            for (size_t c = 0; c < 3; ++c) {
                const double e = o.weight * (std::cbrt(o.value[c] + epsilon) - std::cbrt(d[c] / std::numbers::pi + s[c] * lobe + epsilon));
                sum += e * e;
            }
        }
        return sum;
    };
    const double at = cost(r.ns, r.cd, r.cs);
    CHECK(at == doctest::Approx(r.cost).epsilon(1e-9));  // the reported cost is this cost
    for (int p = 0; p < 7; ++p)
        for (const double f : {0.998, 1.002}) {
            double ns = r.ns;
            std::array<double, 3> d = r.cd, s = r.cs;
            if (p == 0) ns *= f;
            else if (p < 4) d[static_cast<size_t>(p - 1)] *= f;
            else s[static_cast<size_t>(p - 4)] = std::min(1.0, s[static_cast<size_t>(p - 4)] * f);
            CAPTURE(p);
            CAPTURE(f);
            CHECK(cost(ns, d, s) >= at * (1 - 1e-12));
        }
}

namespace {

// Each model of `fit --model` as the renderer evaluates it, from the parameters the fit reports (by
// name): what a preset hands to its technique.
glm::dvec3 renderer_value(const std::string& model, const std::map<std::string, std::vector<double>>& p, const brdf::Directions& d) {
    const auto colour = [&](const char* name) { return glm::dvec3(p.at(name)[0], p.at(name)[1], p.at(name)[2]); };
    if (model == "ashikhmin-fit") return brdf::evaluate(brdf::AshikhminShirleyFit{colour("cd"), colour("cs"), p.at("ns")[0]}, d);
    if (model == "ashikhmin-fresnel" || model == "ashikhmin-aniso")
        return brdf::evaluate(brdf::AshikhminShirley{colour("Rd"), colour("Rs"), p.at("nu")[0], p.at("nv")[0]}, d);
    if (model == "ggx") return brdf::evaluate(brdf::CookTorranceGGX{colour("kd"), colour("F0"), p.at("alpha")[0]}, d);
    if (model == "beckmann") return brdf::evaluate(brdf::CookTorranceBeckmannSchlick{colour("kd"), colour("F0"), p.at("m")[0]}, d);
    if (model == "blinn-phong") return brdf::evaluate(brdf::BlinnPhong{colour("kd"), colour("ks"), p.at("n")[0]}, d);
    if (model == "ward") return brdf::evaluate(brdf::Ward{colour("kd"), colour("ks"), p.at("alpha")[0]}, d);
    FAIL("no renderer model for " << model);
    return {};
}

// Parameters of each model typical of what it is used for (and inside its bounds).
std::map<std::string, std::vector<double>> truth(const std::string& model) {
    if (model == "ashikhmin-fit") return {{"cd", {0.1, 0.2, 0.3}}, {"cs", {0.5, 0.4, 0.3}}, {"ns", {60}}};
    if (model == "ashikhmin-fresnel") return {{"Rd", {0.5, 0.3, 0.2}}, {"Rs", {0.05, 0.06, 0.07}}, {"nu", {200}}, {"nv", {200}}};
    if (model == "ashikhmin-aniso") return {{"Rd", {0.5, 0.3, 0.2}}, {"Rs", {0.05, 0.06, 0.07}}, {"nu", {30}}, {"nv", {400}}};
    if (model == "ggx") return {{"kd", {0.05, 0.1, 0.2}}, {"F0", {0.9, 0.6, 0.3}}, {"alpha", {0.15}}};
    if (model == "beckmann") return {{"kd", {0.3, 0.1, 0.05}}, {"F0", {0.04, 0.04, 0.04}}, {"m", {0.3}}};
    if (model == "blinn-phong") return {{"kd", {0.4, 0.1, 0.1}}, {"ks", {0.3, 0.2, 0.1}}, {"n", {120}}};
    return {{"kd", {0.1, 0.3, 0.1}}, {"ks", {0.1, 0.12, 0.14}}, {"alpha", {0.2}}};  // ward
}

fit::BrdfGrid tabulate_named(const std::string& model, const std::map<std::string, std::vector<double>>& p) {
    return tabulate_model([&](const brdf::Directions& d) { return renderer_value(model, p, d); });
}

}  // namespace

TEST_CASE("every model's basis is the renderer's model, and its derivatives are its slopes") {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto direction = [&] {
        const double z = 0.02 + 0.98 * unit(random), phi = 2 * kPi * unit(random), r = std::sqrt(1 - z * z);
        return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
    };
    for (const std::string& name : fit::model_names()) {
        CAPTURE(name);
        const auto model = fit::find_model(name);
        const std::array<double, 3> a{0.2, 0.3, 0.4}, b{0.5, 0.25, 0.125};
        std::vector<double> shape;
        for (const auto& s : model->shape()) shape.push_back(std::sqrt(s.low * s.high) * (1.0 + 0.3 * shape.size()));  // mid-range, nu != nv
        std::map<std::string, std::vector<double>> named;
        const auto values = model->values(a, b, shape);
        for (size_t i = 0; i < values.size(); ++i) named[model->parameters()[i].name] = values[i];
        for (int trial = 0; trial < 200; ++trial) {
            const glm::dvec3 l = direction(), v = direction();
            const fit::SampleGeometry g = fit::sample_geometry(l, v);
            const auto fitted = model->evaluate(g, a, b, shape);
            const glm::dvec3 rendered = renderer_value(name, named, {{0, 0, 1}, l, v, {1, 0, 0}});
            for (int c = 0; c < 3; ++c) CHECK(fitted[static_cast<size_t>(c)] == doctest::Approx(rendered[c]).epsilon(1e-9).scale(1e-12));
            // d/d ln θ_k by central differences in ln θ (step 1e-6: truncation ~1e-12 relative at these
            // mid-range shapes, rounding ~1e-10): the analytic derivatives within 1e-6.
            fit::Basis d[2];
            model->basis(g, shape.data(), d);
            for (size_t k = 0; k < shape.size(); ++k) {
                std::vector<double> up = shape, down = shape;
                up[k] *= std::exp(1e-6);
                down[k] *= std::exp(-1e-6);
                const fit::Basis u = model->basis(g, up.data()), w = model->basis(g, down.data());
                CHECK(d[k].diffuse == doctest::Approx((u.diffuse - w.diffuse) / 2e-6).epsilon(1e-6).scale(1e-9));
                CHECK(d[k].specular == doctest::Approx((u.specular - w.specular) / 2e-6).epsilon(1e-6).scale(1e-9));
                CHECK(d[k].offset == doctest::Approx((u.offset - w.offset) / 2e-6).epsilon(1e-6).scale(1e-9));
            }
        }
    }
}

TEST_CASE("every model comes back from its own synthetic data, and --model all ranks it first") {
    for (const std::string& name : fit::model_names()) {
        CAPTURE(name);
        const auto expected = truth(name);
        const fit::BrdfGrid grid = tabulate_named(name, expected);
        const std::vector<fit::FitResult> ranking = fit::fit_all_models(fit::observations(grid, 75), {}, false);
        REQUIRE(ranking.size() == fit::model_names().size());
        const fit::FitResult& best = ranking.front();
        CHECK(best.model == name);  // on isotropic data the anisotropic model ties: fewer shape parameters rank first
        CHECK(best.converged);
        // Exact data: the parameters to 1e-6 (the polish stops at relative cost changes of 1e-14).
        for (const fit::FittedParameter& p : best.parameters)
            for (size_t i = 0; i < p.values.size(); ++i) CHECK(p.values[i] == doctest::Approx(expected.at(p.name)[i]).epsilon(1e-6));
        // No other model describes it as well (but the anisotropic one contains the isotropic one).
        if (name != "ashikhmin-fresnel") CHECK(ranking[1].cost > 1e3 * best.cost + 1e-20);
        else CHECK(ranking[1].model == "ashikhmin-aniso");
    }
}

TEST_CASE("other models reach an independent optimum on data they do not describe") {
    struct Case {
        std::string model, data_model;
        RendererModel renderer;
        double low, high, b_upper;
    };
    const RendererModel ggx = [](const brdf::Directions& d, double a, double b, double alpha) {
        return brdf::evaluate(brdf::CookTorranceGGX{glm::dvec3(a), glm::dvec3(b), alpha}, d).r;
    };
    const RendererModel beckmann = [](const brdf::Directions& d, double a, double b, double m) {
        return brdf::evaluate(brdf::CookTorranceBeckmannSchlick{glm::dvec3(a), glm::dvec3(b), m}, d).r;
    };
    const RendererModel blinn = [](const brdf::Directions& d, double a, double b, double n) {
        return brdf::evaluate(brdf::BlinnPhong{glm::dvec3(a), glm::dvec3(b), n}, d).r;
    };
    const RendererModel ward = [](const brdf::Directions& d, double a, double b, double alpha) {
        return brdf::evaluate(brdf::Ward{glm::dvec3(a), glm::dvec3(b), alpha}, d).r;
    };
    // a = Rd (1 − Rs), b = Rs: the renderer's Rd is a / (1 − b).
    const RendererModel fresnel = [](const brdf::Directions& d, double a, double b, double n) {
        return brdf::evaluate(brdf::AshikhminShirley{glm::dvec3(b < 1 ? a / (1 - b) : 0.0), glm::dvec3(b), n, n}, d).r;
    };
    const std::vector<Case> cases = {{"ggx", "beckmann", ggx, 1e-3, 1, 1},           {"beckmann", "ggx", beckmann, 1e-3, 1, 1},
                                     {"blinn-phong", "ggx", blinn, 1e-2, 1e6, kInf}, {"ward", "blinn-phong", ward, 1e-3, 1, kInf},
                                     {"ashikhmin-fresnel", "ggx", fresnel, 1e-2, 1e6, 1}};
    for (const Case& c : cases) {
        CAPTURE(c.model);
        CAPTURE(c.data_model);
        const fit::BrdfGrid grid = tabulate_named(c.data_model, truth(c.data_model));
        const fit::FitResult fit = fit::fit_brdf(grid, {.model = c.model, .limit_deg = 75});
        const double optimum = independent_optimum(grid, 75, c.renderer, c.low, c.high, c.b_upper);
        MESSAGE(c.model, " on ", c.data_model, " data: cost ", fit.cost, " / independent optimum ", optimum, " (", fit.stop_reason, ")");
        CHECK(fit.converged);
        CHECK(fit.cost <= 1.001 * optimum);  // the bar: within 0.1 % of an independent optimum
        CHECK(fit.cost >= 0.999 * optimum);  // and not below it: the two compute the same cost
    }
}

TEST_CASE("the clear-coat option fits the base under the coat (eq. 4.19-4.22)") {
    // Data as the thesis' lacquer files hold them: the coat's Fresnel reflection removed, the base
    // attenuated by the light's transmission 1 − F(θi) into the coat of index 1.5.
    const auto expected = truth("ggx");
    const fit::BrdfGrid base = tabulate_named("ggx", expected);
    fit::BrdfGrid coated = base;
    for (size_t i = 0; i < base.theta_in.size(); ++i)
        for (size_t o = 0; o < base.theta_out.size(); ++o)
            for (size_t p = 0; p < base.phi_out.size(); ++p)
                for (double& x : coated.values[base.index(i, o, p)]) x *= 1.0 - brdf::fresnel_dielectric(1.5, base.light(i).z);
    const fit::FitResult plain = fit::fit_brdf(coated, {.model = "ggx"});
    const fit::FitResult fit = fit::fit_brdf(coated, {.model = "ggx", .clear_coat_index = 1.5});
    CHECK(plain.cost > 1e6 * fit.cost);
    for (const fit::FittedParameter& p : fit.parameters)
        for (size_t i = 0; i < p.values.size(); ++i) CHECK(p.values[i] == doctest::Approx(expected.at(p.name)[i]).epsilon(1e-6));
    CHECK_THROWS_AS(fit::validate({.clear_coat_index = 0.5}), UsageError);
    CHECK_THROWS_AS(fit::validate({.model = "ggx", .solver = fit::Solver::Thesis}), UsageError);
    CHECK_THROWS_AS(fit::validate({.model = "nonsense"}), UsageError);
}

TEST_CASE("--model all with a robust loss fits every model with one scale and ranks them by that objective") {
    // Issue 28: each model chose its own δ and the ranking used the reweighted cost, so models were
    // ranked by different objectives. Outlier-laden data of the thesis' model.
    const std::array<double, 3> cd{0.15, 0.30, 0.45}, cs{0.50, 0.40, 0.20};
    fit::BrdfGrid data = model_grid(120.0, cd, cs);
    for (size_t i = 0; i < data.values.size(); i += 50)
        for (double& c : data.values[i]) c *= 6.0;
    fit::FitOptions options;
    options.loss = fit::Loss::Huber;
    const std::vector<fit::FitResult> ranking = fit::fit_all_models(fit::observations(data, 75), options, true);
    REQUIRE(ranking.size() >= 3);
    for (const fit::FitResult& r : ranking) {
        CAPTURE(r.model);
        CHECK(r.loss_scale_used == ranking.front().loss_scale_used);
        CHECK(r.objective > 0);
    }
    for (size_t i = 1; i < ranking.size(); ++i) CHECK(ranking[i - 1].objective <= ranking[i].objective * (1 + 1e-9));
    CHECK(ranking.front().model == "ashikhmin-fit");  // the data's own model
}

TEST_CASE("near-tied minima are both polished on all samples: a strided search subset cannot pick the worse one") {
    // Issue 28: a MERL file's fit ended 0.35 % above the global optimum. Large data are searched on an
    // evenly strided subset; where two minima nearly tie, the subset can rank them the other way round
    // than all the samples do. Here: a broad lobe (ns 3) plus a sharp one (ns 1000) of weight w on
    // 200 000 random direction pairs (searched on every second one), the sharp lobe 6 % stronger on the
    // samples the search leaves out than on those it sees. Between the w where the subset's two minima
    // tie and the w where all samples' do, the subset prefers the broad minimum and all samples the
    // sharp one: the solver must end at the sharp one.
    const auto model = fit::find_model("ashikhmin-fit");
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const auto hemisphere = [&] {
        const double z = uniform(random), phi = 2 * kPi * uniform(random), s = std::sqrt(1 - z * z);
        return glm::dvec3(s * std::cos(phi), s * std::sin(phi), z);
    };
    const size_t n = 200000;
    std::vector<fit::SampleGeometry> geometry;
    for (size_t i = 0; i < n; ++i) geometry.push_back(fit::sample_geometry(hemisphere(), hemisphere()));
    const auto lobe = [&](const fit::SampleGeometry& g, double ns) { return model->evaluate(g, {0, 0, 0}, {1, 1, 1}, {ns})[0]; };
    const auto data_for = [&](double w, size_t stride) {
        fit::FitData d;
        for (size_t i = 0; i < n; i += stride) {
            const double y = 0.3 * lobe(geometry[i], 3) + w * (i % 2 == 0 ? 0.97 : 1.03) * lobe(geometry[i], 1000);
            d.geometry.push_back(geometry[i]);
            d.values.push_back({y, y, y});
            d.weights.push_back(1.0);
        }
        return d;
    };
    // Each minimum, polished from its lobe.
    const auto polished = [&](const fit::FitData& d, double ns) {
        fit::SeparableSolution start;
        start.shape = {ns};
        start.b = {0.5, 0.5, 0.5};
        return fit::solve_separable(*model, d, {}, &start);
    };
    // Whether the sharp minimum is the better one (or the only one: the polish from the broad lobe
    // ends there too).
    const auto sharp_wins = [&](const fit::FitData& d) {
        const fit::SeparableSolution sharp = polished(d, 1000), broad = polished(d, 3);
        return broad.shape[0] > 50 || sharp.cost < broad.cost;
    };
    // Where each data set's two minima tie: the sharp one wins above it (bisection in ln w).
    const auto tie = [&](size_t stride) {
        double low = 1e-3, high = 0.1;
        for (int i = 0; i < 14; ++i) {
            const double w = std::sqrt(low * high);
            (sharp_wins(data_for(w, stride)) ? high : low) = w;
        }
        return std::sqrt(low * high);
    };
    const double tie_seen = tie(2), tie_all = tie(1);
    MESSAGE("ties: subset at w ", tie_seen, ", all samples at w ", tie_all);
    REQUIRE(tie_all < tie_seen);  // the subset sees the sharp lobe weaker
    const double w = std::sqrt(tie_seen * tie_all);
    const fit::FitData all = data_for(w, 1), seen = data_for(w, 2);
    const fit::SeparableSolution sharp = polished(all, 1000), broad = polished(all, 3), sharp_seen = polished(seen, 1000), broad_seen = polished(seen, 3);
    MESSAGE("w ", w, ": all samples: sharp ", sharp.cost, " (ns ", sharp.shape[0], "), broad ", broad.cost, " (ns ", broad.shape[0], "); subset: sharp ",
            sharp_seen.cost, ", broad ", broad_seen.cost, " (ns ", broad_seen.shape[0], ")");
    REQUIRE(broad.shape[0] < 50);  // two minima in all samples, the sharp one better
    REQUIRE(sharp.cost < broad.cost);
    REQUIRE(broad_seen.shape[0] < 50);  // the subset ranks them the other way round
    REQUIRE(broad_seen.cost < sharp_seen.cost);
    const fit::SeparableSolution s = fit::solve_separable(*model, all);
    CHECK(s.shape[0] > 50);
    CHECK(s.cost <= sharp.cost * (1 + 1e-6));
}
