// The built-in environments' spectral forms: their radiance through the CMFs, Fourier films and the
// CD under them against exact sums and the ground truth (test_environment's executable).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>
#include <numbers>

#include <nlohmann/json.hpp>

#include "image/image_file.hpp"
#include "lighting/environment_sources.hpp"
#include "lighting/image_based_lighting.hpp"
#include "spectral/colorimetry.hpp"
#include "test_support.hpp"

using namespace fxview;
using fxview::test::Result;
using fxview::test::run;
using fxview::test::temp_path;

TEST_CASE("the built-in environments' spectral forms are their RGB radiance: Σ w_k S_k through the CIE 1931 CMFs gives the cube's colour") {
    // Independent of the sky's construction: colord's CMFs integrate the spectra at 1 nm, and the
    // result must be the RGB the background and the RGB techniques see. 1e-3 relative: the cube's
    // float texels and the clipping of daylight's RGB at 0 (12000 K and 5500 K lie inside sRGB; the
    // studio's and furnace's D65 is sRGB's white to 1e-4).
    const spectral::Observer observer = spectral::load_observer("1931");
    for (const char* source : {"sky", "sky:5,4500", "studio", "furnace"}) {
        const lighting::Environment sky = lighting::make_environment(source, 32);
        REQUIRE(sky.spectral.has_value());
        double ybar = 0;
        for (int nm = 360; nm <= 830; ++nm) ybar += observer.y.at(nm);
        const lighting::FloatCube with_discs = sky.radiance_with_discs();  // the weights hold the sun drawn in
        for (int face = 0; face < 6; ++face)
            for (int y = 1; y < 32; y += 5)
                for (int x = 2; x < 32; x += 7) {
                    const glm::vec3 w = sky.spectral->weights.at(face, x, y), rgb = with_discs.at(face, x, y);
                    spectral::Vec3 xyz{};
                    for (int nm = 360; nm <= 830; ++nm) {
                        const size_t i = static_cast<size_t>(nm - 360);
                        const double l = w.x * sky.spectral->spectra[0][i] + w.y * sky.spectral->spectra[1][i] + w.z * sky.spectral->spectra[2][i];
                        xyz[0] += l * observer.x.at(nm) / ybar;
                        xyz[1] += l * observer.y.at(nm) / ybar;
                        xyz[2] += l * observer.z.at(nm) / ybar;
                    }
                    const spectral::Vec3 expected = spectral::xyz_to_linear_srgb_unclipped(xyz);
                    CAPTURE(source); CAPTURE(face); CAPTURE(x); CAPTURE(y);
                    for (int c = 0; c < 3; ++c) CHECK(rgb[c] == doctest::Approx(expected[static_cast<size_t>(c)]).epsilon(1e-3).scale(1e-4));
                }
    }
}

TEST_CASE("Fourier films under the sky: the series of the sky's three spectra matches the exact sum and the CPU reference") {
    const std::string thinfilm = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/thinfilm.fx";
    const std::string scene = " --environment sky:35 --size 32x32 --set Thickness=300 --set Variation=700 --set Brightness=0.5";
    for (const auto& [fourier, exact] : {std::pair{"FresnelFourier", "FresnelExact"}, std::pair{"BubbleFourier", "Bubble"}}) {
        CAPTURE(fourier);
        const Result compare = run("compare " + thinfilm + " -t " + fourier + scene);
        CHECK(compare.exit_code == 0);
        // Against Airy's sum over every nm under the same sky, a method without the series: the rule
        // stops once what is left is below 1e-3 of the light (kSeriesTailLimit), so 2e-3 of the
        // brightest pixel bounds the difference with float rounding to spare.
        const std::string a = temp_path(std::string(fourier) + "-sky.pfm"), b = temp_path(std::string(exact) + "-sky.pfm");
        REQUIRE(run("render " + thinfilm + " -t " + fourier + scene + " --out " + a).exit_code == 0);
        REQUIRE(run("render " + thinfilm + " -t " + exact + scene + " --set Steps=1 --set Lower=360 --set Upper=830 --out " + b).exit_code == 0);
        const image::FloatImage series = image::read_float_image(a), sum = image::read_float_image(b);
        double brightest = 0, worst = 0, lit = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                for (int c = 0; c < 3; ++c) {
                    brightest = std::max<double>(brightest, sum.pixel(x, y)[c]);
                    worst = std::max<double>(worst, std::abs(series.pixel(x, y)[c] - sum.pixel(x, y)[c]));
                    lit += sum.pixel(x, y)[c] > 0.01;
                }
        CHECK(lit > 500);  // the film is seen, not the background alone
        CHECK(brightest < 0.99);  // nothing clipped
        CHECK(worst < 2e-3 * brightest);
    }
}

TEST_CASE("a CD in the white furnace reflects its coating's reflectance in neutral grey, whatever its tracks") {
    // Uniform radiance 1 of D65 from every direction: whatever directions the grating equation picks,
    // every order sees 1, so the disc shows Σ η_m = Reflectance in the furnace's colour, for any track
    // spacing, number of tracks, pit width and view (an analytic result the shader's formulas do not
    // contain). 2e-3: D65 against sRGB's white (1e-4), float sums over 471 wavelengths, and orders
    // turning evanescent inside a band of EnvironmentBand nm (their share then goes to the others).
    const std::string cd = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/cd.fx -t Orders --mesh disc --environment furnace --size 32x32"
                           " --set Lamp=0 --set SubstrateWeight=0 --set Reflectance=0.8";
    for (const std::string settings : {" --set Tracks=10", " --set Tracks=200 --set TrackSpacing=740", " --set PitFraction=0.6 --camera-rotate 40,0,0",
                                       " --set TrackSpacing=5000 --set EnvironmentBand=1 --camera-rotate 0,60,0"}) {
        CAPTURE(settings);
        const std::string out = temp_path("cd-furnace.exr");
        REQUIRE(run("render " + cd + settings + " --out " + out).exit_code == 0);
        const image::FloatImage image = image::read_float_image(out);
        int disc = 0;
        double worst = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const auto p = image.pixel(x, y);
                if (std::abs(p[1] - 1.0f) < 1e-3f) continue;  // the furnace behind the disc
                ++disc;
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(p[c] - 0.8));
            }
        CHECK(disc > 100);
        CHECK(worst < 2e-3);
    }
}

TEST_CASE("compare --ground-truth for films under the sky: the exact film mirroring the sky's model, independent of the weight cube") {
    const std::string thinfilm = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/thinfilm.fx";
    const auto truth_of = [&](const std::string& arguments) {
        const Result r = run("compare " + thinfilm + " " + arguments + " --environment sky:35 --size 32x32 --ground-truth --json");
        CAPTURE(arguments);
        CAPTURE(r.err);
        REQUIRE(r.exit_code == 0);
        const auto json = nlohmann::json::parse(r.out.substr(r.out.find('{')));
        REQUIRE(json.contains("ground_truth"));
        return json["ground_truth"];
    };
    // A soap bubble and oil on water: the techniques' pictures lie within CIEDE2000 1 of the truth
    // on average (the acceptance of issue 25; measured 6e-4 and 3e-3 at 64x64, the cube's bilinear
    // reads of the sun's edge the largest part).
    CHECK(truth_of("-t BubbleFourier --set Thickness=300 --set Variation=700")["mean_delta_e2000"].get<double>() < 1.0);
    CHECK(truth_of("-t FresnelFourier --set FilmIndex=1.5 --set SubstrateIndex=1.33 --set Thickness=150 --set Variation=900")["mean_delta_e2000"].get<double>() < 1.0);
    // The truth is the physical film, not the technique's formula: the thesis' Fresnel model (Code 15,
    // which keeps only the cosine of the phase) lies far from it (measured mean 21.6 at 64x64).
    CHECK(truth_of("-t Fresnel")["mean_delta_e2000"].get<double>() > 5.0);
}

TEST_CASE("compare --ground-truth for the CD's orders in the studio: bands and weight cube against every nm of the model") {
    const Result r = run("compare " + std::string(FXVIEW_SOURCE_EFFECTS_DIR) +
                         "/spectral/cd.fx -t Orders --mesh disc --camera-rotate -25,15,0 --environment studio --set Lamp=0 --size 32x32 --ground-truth --json");
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    const auto truth = nlohmann::json::parse(r.out.substr(r.out.find('{')))["ground_truth"];
    // Measured 0.097 at 64x64 with 10 nm bands; a colour error users would see starts near 1.
    CHECK(truth["mean_delta_e2000"].get<double>() < 0.5);
    CHECK(truth["method"].get<std::string>().find("every nm") != std::string::npos);
}
