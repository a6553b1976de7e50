// The scene light's spectrum (--light-spectrum, a preset's "light_spectrum", the viewer's Scene tab):
// every parameter annotated SceneLight = "spectrum" follows it, the CPU references too; an unknown
// name is a usage error naming the library; an effect with no such parameter says so.
#include <doctest/doctest.h>

#include <fstream>

#include "image/image_file.hpp"
#include "test_support.hpp"

using fxview::test::Result;
using fxview::test::run;
using fxview::test::temp_path;

namespace {
const std::string spectral = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/";
std::vector<float> pixels(const std::string& path) { return fxview::image::read_pfm(path).data; }
}  // namespace

TEST_CASE("every spectral effect's light spectrum follows the scene light's, as --set would set it") {
    for (const std::string effect : {"wavelength.fx -t Phong", "thinfilm.fx -t FresnelExact", "cd.fx -t Thesis"}) {
        CAPTURE(effect);
        const std::string scene = temp_path("scene-light.pfm"), set = temp_path("set-light.pfm"), own = temp_path("own-light.pfm");
        REQUIRE(run("render " + spectral + effect + " --light-spectrum F11 --size 24x24 --out " + scene).exit_code == 0);
        REQUIRE(run("render " + spectral + effect + " --set LightSpectrum=F11 --size 24x24 --out " + set).exit_code == 0);
        REQUIRE(run("render " + spectral + effect + " --size 24x24 --out " + own).exit_code == 0);
        CHECK(pixels(scene) == pixels(set));
        CHECK(pixels(scene) != pixels(own));  // D65 by default: F11 is another light
    }
    // A preset's scene carries it; the user's own --set loses to the scene light while one is set.
    const std::string preset = temp_path("light-spectrum.json");
    std::ofstream(preset) << R"({"parameters": {}, "scene": {"light_spectrum": "A"}})";
    const std::string from_preset = temp_path("preset-light.pfm"), from_set = temp_path("set-a.pfm");
    REQUIRE(run("render " + spectral + "wavelength.fx -t Phong --preset " + preset + " --set LightSpectrum=D65 --size 24x24 --out " + from_preset).exit_code == 0);
    REQUIRE(run("render " + spectral + "wavelength.fx -t Phong --set LightSpectrum=A --size 24x24 --out " + from_set).exit_code == 0);
    CHECK(pixels(from_preset) == pixels(from_set));
}

TEST_CASE("compare: the CPU reference takes the scene light's spectrum too") {
    const Result r = run("compare " + spectral + "wavelength.fx -t Phong --light-spectrum F11 --size 24x24");
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("pass") != std::string::npos);
}

TEST_CASE("an unknown light spectrum is a usage error naming the library; an effect without one says so") {
    const Result unknown = run("render " + spectral + "wavelength.fx --light-spectrum Candle --size 16x16 --out " + temp_path("x.png"));
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.err.find("light spectrum 'Candle' is not in the spectral library") != std::string::npos);
    CHECK(unknown.err.find("D65") != std::string::npos);
    const Result rgb = run("render " + std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx --light-spectrum F11 --size 16x16 --out " +
                           temp_path("x.png"));
    CHECK(rgb.exit_code == 0);
    CHECK(rgb.err.find("no parameter of this effect takes the light's spectrum") != std::string::npos);
    std::ofstream(temp_path("bad-light.json")) << R"({"parameters": {}, "scene": {"light_spectrum": 5}})";
    const Result bad = run("render " + spectral + "wavelength.fx --preset " + temp_path("bad-light.json") + " --out " + temp_path("x.png"));
    CHECK(bad.exit_code == 1);
    CHECK(bad.err.find("light_spectrum") != std::string::npos);
}
