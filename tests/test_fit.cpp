// The BRDF fitter (seed 000 ch. 4.2-4.3): the grid and its solid-angle weights against closed forms,
// the file format's round trip and errors, eq. 4.29 against numerical derivatives, and the thesis'
// own validation: synthetic BRDFs made with the model itself must be fitted with zero error.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>

#include "fit/fit_preview.hpp"
#include "brdf/models.hpp"
#include "core/error.hpp"
#include "fit/brdf_fit.hpp"
#include "fit/brdf_grid.hpp"
#include "fit/merl.hpp"
#include "test_support.hpp"

using namespace fxview;

namespace {

constexpr double kPi = std::numbers::pi;

// A synthetic measurement of the eq. 4.28 model.
fit::BrdfGrid synthetic(double ns, std::array<double, 3> cd, std::array<double, 3> cs) {
    return fit::tabulate(fit::thesis_grid(), [&](const glm::dvec3& l, const glm::dvec3& v) {
        const double lobe = fit::ashikhmin_lobe(l, v, ns);
        return std::array<double, 3>{cd[0] / kPi + cs[0] * lobe, cd[1] / kPi + cs[1] * lobe, cd[2] / kPi + cs[2] * lobe};
    });
}

}  // namespace

TEST_CASE("the thesis' grid: 75 924 values, weights that sum to the quarter sphere's solid angle") {
    const fit::BrdfGrid grid = fit::thesis_grid();
    CHECK(grid.size() * 3 == 75924);  // eq. 4.15
    double sum = 0;
    for (double w : fit::solid_angle_weights(grid, 90.0)) sum += w;
    CHECK(sum == doctest::Approx(kPi).epsilon(1e-12));  // a quarter sphere: π sr
    // Limited to 75°: the cap between 0° and 75° over half the azimuths, π (1 − cos 75°).
    sum = 0;
    for (double w : fit::solid_angle_weights(grid, 75.0)) sum += w;
    CHECK(sum == doctest::Approx(kPi * (1.0 - std::cos(75.0 * kPi / 180.0))).epsilon(1e-12));
    // Directions: light on −x, camera starting at +x.
    CHECK(grid.light(18).x == doctest::Approx(-1.0));
    CHECK(grid.camera(36, 0).x == doctest::Approx(1.0));
    CHECK(grid.camera(36, 35).x == doctest::Approx(-1.0));
}

TEST_CASE("BRDF grid files: round trip, and errors that name file and line") {
    const fit::BrdfGrid grid = synthetic(40, {0.1, 0.2, 0.3}, {0.3, 0.2, 0.1});
    const std::string path = test::temp_path("grid.csv");
    fit::write_brdf_grid(grid, path);
    const fit::BrdfGrid back = fit::read_brdf_grid(path);
    CHECK(back.theta_in == grid.theta_in);
    CHECK(back.phi_out == grid.phi_out);
    CHECK(back.values == grid.values);  // 17 significant digits: exact

    const auto write = [](const std::string& name, const std::string& text) {
        const std::string p = test::temp_path(name);
        std::ofstream(p) << text;
        return p;
    };
    const auto message = [](const std::string& p) {
        try {
            fit::read_brdf_grid(p);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string header = "theta_in_deg,theta_out_deg,phi_out_deg,r,g,b\n";
    CHECK(message(write("noheader.csv", "0,0,0,1,1,1\n")).find("noheader.csv:1: expected the header") != std::string::npos);
    CHECK(message(write("nan.csv", header + "0,0,0,1,x,1\n")).find("nan.csv:2: 'x' is not a finite number") != std::string::npos);
    CHECK(message(write("short.csv", header + "0,0,0,1,1\n")).find("short.csv:2: expected 6 values") != std::string::npos);
    CHECK(message(write("angle.csv", header + "0,95,0,1,1,1\n")).find("angle.csv:2: angles must lie") != std::string::npos);
    CHECK(message(write("repeat.csv", header + "0,0,0,1,1,1\n0,0,0,2,2,2\n")).find("repeat.csv:3: repeats the sample of line 2") !=
          std::string::npos);
    CHECK(message(write("hole.csv", header + "0,0,0,1,1,1\n0,10,0,1,1,1\n5,0,0,1,1,1\n")).find("do not form a complete grid") !=
          std::string::npos);
    CHECK(message(test::temp_path("missing.csv")).find("no such file") != std::string::npos);
}

TEST_CASE("synthetic BRDFs of the model are fitted exactly (the thesis' own check of its LM)") {
    const std::array<double, 3> cd{0.10, 0.25, 0.40}, cs{0.60, 0.45, 0.30};
    const fit::FitResult fit = fit::fit_brdf(synthetic(80.0, cd, cs), {.solver = fit::Solver::Thesis});
    // Start ns = 25, cd = cs = 0.2 as in the thesis; 500 iterations. The data are the model's, so
    // the minimum is exact; 1e-6 is far below any fitting effect and far above double rounding.
    CHECK(fit.ns == doctest::Approx(80.0).epsilon(1e-6));
    for (size_t c = 0; c < 3; ++c) {
        CHECK(fit.cd[c] == doctest::Approx(cd[c]).epsilon(1e-6));
        CHECK(fit.cs[c] == doctest::Approx(cs[c]).epsilon(1e-6));
    }
    CHECK(fit.error_rgb < 1e-6);
    CHECK(fit.samples_used == 16 * 31 * 36);  // θi, θo ≤ 75°
    // Rejected steps keep the parameters, so the weighted cost LM minimises never grows (the
    // unweighted e of eq. 4.1 may: it weighs grazing samples more than the residual does).
    for (size_t i = 1; i < fit.stage1.cost.size(); ++i) CHECK(fit.stage1.cost[i] <= fit.stage1.cost[i - 1]);
    // The renderer's form (eq. 4.23/4.24) describes the same BRDF.
    CHECK(fit.rs == doctest::Approx(0.60));
    for (size_t c = 0; c < 3; ++c) {
        CHECK((1.0 - fit.rs) * fit.rd_renderer[c] == doctest::Approx(fit.cd[c]));
        CHECK(fit.rs * fit.cs_renderer[c] == doctest::Approx(fit.cs[c]));
    }
    CHECK(fit.converged);
    // The default solver finds the same exact minimum, without a start.
    const fit::FitResult global = fit::fit_brdf(synthetic(80.0, cd, cs), {});
    CHECK(global.ns == doctest::Approx(80.0).epsilon(1e-6));
    for (size_t c = 0; c < 3; ++c) {
        CHECK(global.cd[c] == doctest::Approx(cd[c]).epsilon(1e-6));
        CHECK(global.cs[c] == doctest::Approx(cs[c]).epsilon(1e-6));
    }
    CHECK(global.converged);
    CHECK(global.warnings.empty());
}

TEST_CASE("eq. 4.29: the analytic derivative of the lobe by ns matches central differences") {
    const glm::dvec3 l = glm::normalize(glm::dvec3(-0.4, 0.0, 1.0)), v = glm::normalize(glm::dvec3(0.35, 0.1, 1.0));
    for (const double ns : {5.0, 50.0, 400.0}) {
        const double h = 1e-5 * ns;
        const double numeric = (fit::ashikhmin_lobe(l, v, ns + h) - fit::ashikhmin_lobe(l, v, ns - h)) / (2 * h);
        const double n_dot_h = glm::normalize(l + v).z;
        const double analytic = fit::ashikhmin_lobe(l, v, ns) * (1.0 / (ns + 1.0) + std::log(n_dot_h));
        CAPTURE(ns);
        CHECK(analytic == doctest::Approx(numeric).epsilon(1e-7));  // central differences: O(h²) ~ 1e-10 relative
    }
}

TEST_CASE("fitting another model's data: a finite error that the fit reduces, never NaN") {
    // GGX (the PBR sandbox's model) is not in the Ashikhmin-Shirley family: the fit must settle on a
    // lobe of comparable width and leave a residual error.
    const brdf::MetallicRoughness ggx{{0.9, 0.6, 0.3}, 1.0, 0.3};
    const fit::BrdfGrid data = fit::tabulate(fit::thesis_grid(), [&](const glm::dvec3& l, const glm::dvec3& v) {
        const glm::dvec3 f = brdf::evaluate(ggx, {{0, 0, 1}, l, v, {1, 0, 0}});
        return std::array<double, 3>{f.r, f.g, f.b};
    });
    const fit::FitResult fit = fit::fit_brdf(data, {});
    CHECK(std::isfinite(fit.error_rgb));
    const fit::FitResult thesis = fit::fit_brdf(data, {.solver = fit::Solver::Thesis});
    CHECK(thesis.error_per_iteration.back() < 0.5 * thesis.error_per_iteration.front());
    CHECK(fit.cost <= thesis.cost * (1 + 1e-9));
    CHECK(fit.ns > 10);
    CHECK(fit.cs[0] > fit.cs[2]);  // gold-like: more red than blue in the highlight
    CHECK_THROWS_AS(fit::fit_brdf(data, {.limit_deg = 0}), UsageError);
    // Without a limit the grazing samples enter (the light at 90° only with weight 0, left out): still finite.
    const fit::FitResult all = fit::fit_brdf(data, {.limit_deg = 90});
    CHECK(std::isfinite(all.error_rgb));
    CHECK(all.ns > 0);
}

TEST_CASE("MERL binary BRDFs: the reference reader's bins, scales and errors") {
    const auto deg = [](double d) { return d * kPi / 180.0; };
    const auto dir = [&](double theta, double phi) {
        return glm::dvec3(std::sin(deg(theta)) * std::cos(deg(phi)), std::sin(deg(theta)) * std::sin(deg(phi)), std::cos(deg(theta)));
    };
    // Bins worked out by hand from BRDFRead.cpp's formulas (θh index = floor(sqrt(θh/90° · 8100)),
    // θd index = floor(θd / 1°), φd index = floor(φd / 1°) after folding into [0°, 180°)):
    // light = view at 40.5°: θh = 40.5° → sqrt(3645) = 60.4; θd = 0.
    CHECK(fit::merl_bins(dir(40.5, 0), dir(40.5, 0)) == std::array<int, 3>{60, 0, 0});
    // Mirror pair at 30.5°: h = n (θh = 0), the difference vector is the light itself: θd = 30.5°,
    // φd = 180° → clamped to the last bin.
    const double s = std::sin(deg(30.5)), c = std::cos(deg(30.5));  // exact zeros in y: h is exactly n
    CHECK(fit::merl_bins({-s, 0, c}, {s, 0, c}) == std::array<int, 3>{0, 30, 179});
    // Light along n, view at 50.3° towards +y: θh = θd = 25.15° → sqrt(2263.5) = 47.6 and 25.
    CHECK(fit::merl_bins(dir(0, 0), dir(50.3, 90)) == std::array<int, 3>{47, 25, 179});

    // A file whose every bin holds one colour reads back as that colour in 1/sr after the scales.
    fit::MerlBrdf constant;
    const size_t n = 90 * 90 * 180;
    constant.data.assign(3 * n, 0.0);
    std::fill(constant.data.begin(), constant.data.begin() + n, 0.3 * 1500.0);
    std::fill(constant.data.begin() + n, constant.data.begin() + 2 * n, 0.2 * 1500.0 / 1.15);
    std::fill(constant.data.begin() + 2 * n, constant.data.end(), 0.1 * 1500.0 / 1.66);
    const std::string path = test::temp_path("constant.binary");
    fit::write_merl(constant, path);
    const fit::BrdfGrid grid = fit::merl_to_grid(fit::read_merl(path), fit::thesis_grid());
    CHECK(grid.values[1234][0] == doctest::Approx(0.3).epsilon(1e-14));
    CHECK(grid.values[1234][1] == doctest::Approx(0.2).epsilon(1e-14));
    CHECK(grid.values[1234][2] == doctest::Approx(0.1).epsilon(1e-14));
    // A Lambertian MERL file is fitted as cd = π f, cs = 0.
    const fit::FitResult lambert = fit::fit_brdf(grid, {});
    CHECK(lambert.cd[0] == doctest::Approx(0.3 * kPi).epsilon(1e-6));
    CHECK(std::abs(lambert.cs[0]) < 1e-6);

    // Wrong header, truncation: errors name the file.
    const std::string bad = test::temp_path("bad.binary");
    { std::ofstream(bad, std::ios::binary).write("\x01\x00\x00\x00\x02\x00\x00\x00\x03\x00\x00\x00", 12); }
    CHECK_THROWS_WITH_AS(fit::read_merl(bad), doctest::Contains("bad.binary: not a MERL BRDF"), Error);
    const std::string truncated = test::temp_path("truncated.binary");
    {
        std::ofstream out(truncated, std::ios::binary);
        const std::int32_t dims[3] = {90, 90, 180};
        out.write(reinterpret_cast<const char*>(dims), sizeof dims);
        out.write(reinterpret_cast<const char*>(constant.data.data()), 1000 * sizeof(double));
    }
    CHECK_THROWS_WITH_AS(fit::read_merl(truncated), doctest::Contains("truncated.binary: truncated"), Error);
}

TEST_CASE("MERL files are fitted at full density: every measured bin at its centre, weighted by its measure") {
    // Each bin's centre falls back into that bin under the reference reader's indexing (BRDFRead.cpp),
    // so the observations are the table's own samples, not a resampling.
    for (int h : {0, 1, 17, 45, 89})
        for (int d : {0, 30, 89})
            for (int p : {0, 90, 179}) {
                const fit::BinDirections b = fit::merl_bin_centre(h, d, p);
                if (b.l.z <= 0 || b.v.z <= 0) continue;
                CAPTURE(h);
                CAPTURE(d);
                CAPTURE(p);
                CHECK(fit::merl_bins(b.l, b.v) == std::array<int, 3>{h, d, p});
            }

    // The weights integrate: Σ w cos θo is ∫∫ cos θi cos θo dωi dωo / ∫∫ cos θi dωi dωo = π² / (2π²) = ½
    // over the two hemispheres (the table's half range of φd holds each pair once up to the swap of
    // light and view, which leaves both integrals' ratio unchanged). A Jacobian without Rusinkiewicz's
    // cos θd would give 0.41. The midpoint rule over 1° bins and the bins cut by the horizon leave an
    // error of order the bin size squared near the horizon: 2e-3 bounds it.
    const fit::MerlBrdf white = fit::tabulate_merl([](const glm::dvec3&, const glm::dvec3&) { return std::array<double, 3>{1, 1, 1}; });
    const fit::Observations all = fit::observations(white, 90.0);
    double mean_cos_out = 0, weights = 0;
    for (const fit::Observation& o : all.samples) {
        mean_cos_out += o.weight * o.v.z;
        weights += o.weight;
    }
    CHECK(weights == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(mean_cos_out == doctest::Approx(0.5).epsilon(2e-3));
    CHECK(all.total == 90u * 90u * 180u);
    CHECK(all.samples.size() + all.masked + all.outside_limit == all.total);
    CHECK(all.samples.size() > 1'000'000);  // more than a million pairs: the database's density

    // A MERL table of the model itself is fitted exactly from all its bins; unmeasured bins (negative,
    // as below the horizon in the database) are counted and left out.
    const std::array<double, 3> cd{0.15, 0.30, 0.45}, cs{0.50, 0.40, 0.20};
    fit::MerlBrdf model = fit::tabulate_merl([&](const glm::dvec3& l, const glm::dvec3& v) {
        const double lobe = fit::ashikhmin_lobe(l, v, 120.0);
        return std::array<double, 3>{cd[0] / kPi + cs[0] * lobe, cd[1] / kPi + cs[1] * lobe, cd[2] / kPi + cs[2] * lobe};
    });
    // A valid table's bins below the horizon are outside the domain, not gaps: no warning for them
    // (issue 28: every valid MERL file warned about its negative samples).
    const size_t unmeasured_before = fit::observations(model, 75.0).masked;
    CHECK(unmeasured_before == 0);
    const size_t bins = 90 * 90 * 180;
    for (size_t i = 0; i < bins; i += 97) model.data[i] = -1.0;  // a sensor's gaps, in red
    const fit::Observations data = fit::observations(model, 75.0);
    CHECK(data.masked > unmeasured_before);
    const fit::FitResult fit = fit::fit_brdf(data, {});
    CHECK(fit.samples_used == static_cast<int>(data.samples.size()));
    CHECK(fit.samples_masked == data.masked);
    // Exact data of the model: 1e-6 as for the grid, far below fitting effects, far above rounding.
    CHECK(fit.ns == doctest::Approx(120.0).epsilon(1e-6));
    for (size_t c = 0; c < 3; ++c) {
        CHECK(fit.cd[c] == doctest::Approx(cd[c]).epsilon(1e-6));
        CHECK(fit.cs[c] == doctest::Approx(cs[c]).epsilon(1e-6));
    }
    CHECK(fit.converged);
}

TEST_CASE("the fit preview puts the mirror side in each panel's centre, signs the difference and greys rows outside the fit") {
    // Measured: a narrow lobe around the mirror direction (phi_out = 0, theta_out = theta_in);
    // model: the same lobe scaled by 0.5, so measured - model is positive (red) at the lobe only.
    fit::BrdfGrid measured = fit::uniform_grid(3, 5, 7);  // θi 0/45/90, θo 0..90 in 22.5°, φo 0..180 in 30°
    fit::BrdfGrid model = measured;
    for (size_t i = 0; i < 3; ++i)
        for (size_t o = 0; o < 5; ++o)
            for (size_t p = 0; p < 7; ++p) {
                const double lobe = (p == 0 && measured.theta_out[o] == measured.theta_in[i]) ? 1.0 : 0.0;
                measured.values[measured.index(i, o, p)] = {lobe, lobe, lobe};
                model.values[model.index(i, o, p)] = {0.5 * lobe, 0.5 * lobe, 0.5 * lobe};
            }
    fit::PreviewOptions options;
    options.brighten = 1.0;
    options.limit_deg = 60.0;
    const fit::FitPreview preview = fit::fit_preview(measured, model, options);
    const int panel = 2 * 7 - 1, centre = 6;
    CHECK(preview.image.width == 3 * panel + 2);
    CHECK(preview.image.height == 3 * 5 + 2 + 1 + 4);  // rows, two block separators, a gap, the legend
    CHECK(preview.difference_scale == doctest::Approx(0.5));
    // θi = 45°, θo = 45° is row 1·(5 + 1) + 2: the lobe in the centre column of each panel, nowhere else.
    const int row = 1 * 6 + 2;
    CHECK(preview.image.pixel(centre, row)[0] == 1.0f);
    CHECK(preview.image.pixel(centre - 1, row)[0] == 0.0f);
    CHECK(preview.image.pixel(centre + 1, row)[0] == 0.0f);
    CHECK(preview.image.pixel(panel + 1 + centre, row)[0] == 0.5f);
    const float* difference = preview.image.pixel(2 * (panel + 1) + centre, row);
    CHECK(difference[0] == 1.0f);  // measured above the model at full scale: pure red
    CHECK(difference[2] == 0.0f);
    // Separators between panels and between θi blocks are grey.
    CHECK(preview.image.pixel(panel, 0)[1] == 0.5f);
    CHECK(preview.image.pixel(0, 5)[1] == 0.5f);
    // θo = 67.5° is outside the 60° limit: greyed (never black, never the data's value).
    const float* greyed = preview.image.pixel(0, 3);
    CHECK(greyed[0] > 0.0f);
    CHECK(greyed[0] < 0.5f);
    // The legend runs from blue (below the model) at the left to red at the right.
    const float* left = preview.image.pixel(2 * (panel + 1), preview.image.height - 1);
    const float* right = preview.image.pixel(2 * (panel + 1) + panel - 1, preview.image.height - 1);
    CHECK(left[2] == 1.0f);
    CHECK(right[0] == 1.0f);
}

TEST_CASE("samples with the camera at the horizon are left out even at --limit 90") {
    // Issue 28: with --limit 90 the θo = 90° row of a grid (values to 3e32 for 1/(n·v) models)
    // dominated the fit. Light and camera at the horizon count as outside the limit.
    const fit::BrdfGrid grid = fit::uniform_grid(3, 5, 7);  // θi and θo reach 90°
    const fit::Observations data = fit::observations(grid, 90.0);
    REQUIRE(!data.samples.empty());
    for (const fit::Observation& o : data.samples) {
        CHECK(o.l.z > 1e-9);
        CHECK(o.v.z > 1e-9);
    }
    CHECK(data.samples.size() + data.masked + data.outside_limit == data.total);
}
