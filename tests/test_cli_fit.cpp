// The fxview binary's fitting commands (brdf-grid, fit) as a user calls them: synthetic data come
// back as their parameters, bad input is refused naming file and line (test_cli's executable).
#include <doctest/doctest.h>

#include "test_support.hpp"
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <iterator>
#include <cmath>
#include <map>
#include <numbers>
#include <cstdint>
#include <tuple>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "image/image_file.hpp"

using fxview::test::Result;
using fxview::test::run;
using fxview::test::temp_path;

TEST_CASE("brdf-grid and fit: synthetic data of the fit model come back as its parameters") {
    const std::string data = temp_path("fit/synthetic.csv"), preset = temp_path("fit/preset.json"), preview = temp_path("fit/preview.png");
    REQUIRE(run("brdf-grid --model ashikhmin-fit --param cd=0.1,0.2,0.3 --param cs=0.5,0.4,0.3 --param ns=60 --out " + data).exit_code == 0);
    const Result r = run("fit " + data + " --json --preset " + preset + " --preview " + preview);
    REQUIRE(r.exit_code == 0);
    const auto json = nlohmann::json::parse(r.out);
    CHECK(json["ns"].get<double>() == doctest::Approx(60.0).epsilon(1e-6));  // exact data: exact fit
    CHECK(json["cs"][0].get<double>() == doctest::Approx(0.5).epsilon(1e-6));
    CHECK(json["cd"][2].get<double>() == doctest::Approx(0.3).epsilon(1e-6));
    CHECK(json["error_rgb"].get<double>() < 1e-6);
    CHECK(std::filesystem::file_size(preview) > 1000);
    // The preset renders the fitted BRDF with effects/brdf/analytic.fx.
    CHECK(run(std::string("render ") + FXVIEW_SOURCE_EFFECTS_DIR + "/brdf/analytic.fx --preset " + preset + " --size 32x32 --out " +
              temp_path("fit/render.png"))
              .exit_code == 0);
}

TEST_CASE("fit --model all ranks every model; the best one's preset renders with its technique") {
    const std::string data = temp_path("fit/ggx.csv"), preset = temp_path("fit/ggx-preset.json"), ranking = temp_path("fit/ranking.csv");
    REQUIRE(run("brdf-grid --model ggx --param kd=0.05,0.1,0.2 --param f0=0.9,0.6,0.3 --param alpha=0.15 --samples 10 19 19 --out " + data)
                .exit_code == 0);
    const Result r = run("fit " + data + " --model all --json --preset " + preset + " --out " + ranking);
    REQUIRE(r.exit_code == 0);
    const auto json = nlohmann::json::parse(r.out);
    REQUIRE(json["ranking"].size() == 7);  // a grid can show anisotropy: all seven models
    CHECK(json["model"] == "ggx");
    CHECK(json["ranking"][0]["model"] == "ggx");
    CHECK(json["parameters"]["alpha"].get<double>() == doctest::Approx(0.15).epsilon(1e-6));  // exact data: exact fit
    CHECK(json["parameters"]["F0"][0].get<double>() == doctest::Approx(0.9).epsilon(1e-6));
    for (size_t i = 1; i < json["ranking"].size(); ++i)
        CHECK(json["ranking"][i]["weighted_cost"].get<double>() >= json["ranking"][i - 1]["weighted_cost"].get<double>());
    const auto preset_json = nlohmann::json::parse(std::ifstream(preset));
    CHECK(preset_json["technique"] == "CookTorranceGGX");
    CHECK(preset_json["parameters"]["GGXAlpha"].get<double>() == doctest::Approx(0.15).epsilon(1e-6));
    CHECK(run(std::string("render ") + FXVIEW_SOURCE_EFFECTS_DIR + "/brdf/analytic.fx --preset " + preset + " --size 32x32 --out " +
              temp_path("fit/ggx.png"))
              .exit_code == 0);
    std::ifstream csv(ranking);
    std::string header, first;
    std::getline(csv, header);
    std::getline(csv, first);
    CHECK(header.rfind("rank,model,weighted_cost", 0) == 0);
    CHECK(first.rfind("1,ggx,", 0) == 0);
    // The text table names every model, best first.
    const Result text = run("fit " + data + " --model all");
    CHECK(text.out.find("1    ggx") != std::string::npos);
    CHECK(text.out.find("ward") != std::string::npos);
}

TEST_CASE("fit --model: unknown models, the thesis solver on other models and anisotropy on MERL files are usage errors") {
    const std::string data = temp_path("fit/small.csv"), merl = temp_path("fit/small.binary");
    REQUIRE(run("brdf-grid --model ggx --samples 4 7 7 --out " + data).exit_code == 0);
    CHECK(run("fit " + data + " --model nonsense").exit_code == 2);
    CHECK(run("fit " + data + " --model ggx --solver thesis").exit_code == 2);
    CHECK(run("fit " + data + " --model all --solver thesis").exit_code == 2);  // not silently one model
    CHECK(run("fit " + data + " --clear-coat 0.5").exit_code == 2);
    REQUIRE(run("brdf-grid --model ggx --merl-out --out " + merl).exit_code == 0);
    const Result aniso = run("fit " + merl + " --model ashikhmin-aniso");
    CHECK(aniso.exit_code == 2);
    CHECK(aniso.err.find("isotropic") != std::string::npos);
}

TEST_CASE("fit and brdf-grid reject bad input: exit 2 for arguments, 1 naming file and line for data") {
    CHECK(run("brdf-grid --model nonsense --out " + temp_path("x.csv")).exit_code == 2);
    CHECK(run("brdf-grid --model pbr --param shininess=3 --out " + temp_path("x.csv")).exit_code == 2);
    CHECK(run("fit " + temp_path("x.csv") + " --limit 95").exit_code == 2);
    CHECK(run("fit " + temp_path("x.csv") + " --solver thesis --residual cbrt").exit_code == 2);
    CHECK(run("fit " + temp_path("x.csv") + " --loss huber --loss-scale -1").exit_code == 2);
    CHECK(run("fit " + temp_path("x.csv") + " --residual sqrt").exit_code == 2);
    const std::string broken = temp_path("broken-grid.csv");
    std::ofstream(broken) << "theta_in_deg,theta_out_deg,phi_out_deg,r,g,b\n0,0,0,1,1\n";
    const Result r = run("fit " + broken);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("broken-grid.csv:2:") != std::string::npos);

    // A number followed by anything else is not a number (strtod would read 0.25 and stop).
    const std::string partial = temp_path("partial-number.csv");
    std::ofstream(partial) << "theta_in_deg,theta_out_deg,phi_out_deg,r,g,b\n0,0,0,0.25garbage,1,1\n";
    const Result p = run("fit " + partial);
    CHECK(p.exit_code == 1);
    CHECK(p.err.find("partial-number.csv:2: '0.25garbage' is not a finite number") != std::string::npos);

    // Model parameters outside the model's domain, and grids beyond the documented bound.
    for (const char* args : {"--param ns=-5", "--param ns=nan", "--param ns=1,2", "--model pbr --param roughness=0",
                             "--model pbr --param base=1.5", "--model ashikhmin-shirley --param nu=0", "--samples 8000 2 2",
                             "--samples 2000 2000 2000", "--samples 1 19 36"}) {
        CAPTURE(args);
        const Result bad = run(std::string("brdf-grid ") + args + " --out " + temp_path("x.csv"));
        CHECK(bad.exit_code == 2);
        CHECK(bad.err.find("fxview") != std::string::npos);
    }

    // MERL headers with impossible dimensions are rejected before anything is allocated.
    for (const std::int32_t dims : {-180, 0, 1 << 30}) {
        const std::string merl = temp_path("dims.binary");
        {
            std::ofstream out(merl, std::ios::binary);
            const std::int32_t header[3] = {90, 90, dims};
            out.write(reinterpret_cast<const char*>(header), sizeof header);
        }
        const Result m = run("fit " + merl);
        CAPTURE(dims);
        CHECK(m.exit_code == 1);
        CHECK(m.err.find("dims.binary: not a MERL BRDF") != std::string::npos);
    }
}
