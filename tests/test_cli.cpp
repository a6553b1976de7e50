// The fxview binary as a user calls it: JSON output parsed and checked, files written and read
// back, exit code 2 for nonsense arguments and 1 for I/O or data failures, never a crash.
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

TEST_CASE("pick --json returns the facing normal at the centre of a sphere") {
    for (const char* backend : {"egl", "osmesa"}) {
        CAPTURE(backend);
        const Result r = run(std::string("pick --at 32,32 --size 64x64 --json --backend ") + backend);
        REQUIRE(r.exit_code == 0);
        const auto json = nlohmann::json::parse(r.out);
        CHECK(json["x"] == 32);
        CHECK(json["y"] == 32);
        // Tolerance as in test_render: half a pixel off axis at 64x64 tilts the normal by ~0.013.
        CHECK(std::abs(json["normal"][0].get<double>()) < 0.02);
        CHECK(std::abs(json["normal"][1].get<double>()) < 0.02);
        CHECK(json["normal"][2].get<double>() > 0.98);
        CHECK(json["rgba"].size() == 4);
        CHECK(json["rgba"][3].get<double>() == 1.0);
        // sRGB of the mapped value 0.5 is 188; the blue channel is 1.0 -> 255; alpha 255.
        const auto rgba8 = json["rgba8"];
        CHECK(rgba8[2] == 255);
        CHECK(rgba8[3] == 255);
        const std::uint32_t packed = rgba8[0].get<std::uint32_t>() | rgba8[1].get<std::uint32_t>() << 8 |
                                     rgba8[2].get<std::uint32_t>() << 16 | rgba8[3].get<std::uint32_t>() << 24;
        CHECK(json["packed"].get<std::uint32_t>() == packed);
    }
}

TEST_CASE("pick --no-srgb reports linear 8-bit values") {
    const Result srgb = run("pick --at 32,32 --size 64x64 --json");
    const Result linear = run("pick --at 32,32 --size 64x64 --json --no-srgb");
    REQUIRE(srgb.exit_code == 0);
    REQUIRE(linear.exit_code == 0);
    const auto a = nlohmann::json::parse(srgb.out), b = nlohmann::json::parse(linear.out);
    CHECK(a["rgba"] == b["rgba"]);  // the float value does not depend on the display encoding
    CHECK(a["rgba8"][0].get<int>() > b["rgba8"][0].get<int>());  // sRGB lifts mid-tones (0.5 -> 188 vs 128)
    CHECK(b["encoding"] == "linear");
}

TEST_CASE("render writes PNG, EXR and PFM; the float files hold the exact picked values") {
    const std::string exr = temp_path("cli.exr"), pfm = temp_path("cli.pfm"), png = temp_path("sub/cli.png");
    std::filesystem::remove_all(temp_path("sub"));
    REQUIRE(run("render --size 64x48 --out " + exr).exit_code == 0);
    REQUIRE(run("render --size 64x48 --out " + pfm).exit_code == 0);
    REQUIRE(run("render --size 64x48 --out " + png).exit_code == 0);  // creates the folder
    CHECK(std::filesystem::file_size(png) > 100);
    const auto from_exr = fxview::image::read_float_image(exr);
    const auto from_pfm = fxview::image::read_float_image(pfm);
    CHECK(from_exr.width == 64);
    CHECK(from_exr.height == 48);
    CHECK(from_exr.data == from_pfm.data);
    const auto pick = nlohmann::json::parse(run("pick --size 64x48 --at 40,20 --json").out);
    for (int c = 0; c < 4; ++c) CHECK(from_exr.pixel(40, 20)[c] == pick["rgba"][c].get<float>());
}

TEST_CASE("info reports a GL 4.5 core context for the headless backends") {
    for (const char* backend : {"egl", "egl-device", "osmesa"}) {
        CAPTURE(backend);
        const Result r = run(std::string("info --json --backend ") + backend);
        REQUIRE(r.exit_code == 0);
        const auto json = nlohmann::json::parse(r.out);
        CHECK(json["core_profile"] == true);
        CHECK(json["major"].get<int>() * 10 + json["minor"].get<int>() >= 45);
        CHECK(!json["renderer"].get<std::string>().empty());
    }
}

TEST_CASE("EGL's device platform (the fallback for drivers without surfaceless) renders the same picture") {
    // Mesa offers both platforms, so the path an NVIDIA driver may take runs here too; the pixels
    // must be bit-identical since the same rasteriser draws them.
    const std::string surfaceless = temp_path("surfaceless.pfm"), device = temp_path("device.pfm");
    REQUIRE(run("render --size 64x64 --mesh torus --out " + surfaceless).exit_code == 0);
    REQUIRE(run("render --size 64x64 --mesh torus --backend egl-device --out " + device).exit_code == 0);
    CHECK(fxview::image::read_float_image(surfaceless).data == fxview::image::read_float_image(device).data);
}

TEST_CASE("nonsense arguments exit with 2 and say what is wrong") {
    const std::pair<const char*, const char*> cases[] = {
        {"", "subcommand"},
        {"frobnicate", "frobnicate"},
        {"render --backend vulkan", "unknown backend 'vulkan'"},
        {"render --size 0x64", "--size"},
        {"render --size banana", "--size"},
        {"render --samples -3", "--samples"},
        {"render --mesh dodecahedron", "unknown mesh 'dodecahedron'"},
        {"render --camera-rotate 1,2", "--camera-rotate"},
        {"render --debug-view xray", "unknown debug view"},
        {"render --out picture.gif", "unsupported image type"},
        {"pick --size 64x64", "--at"},
        {"pick --size 64x64 --at 64,0", "outside"},
        {"pick --at 1,2,3", "--at"},
        {"info --backend metal", "unknown backend"},
        {"render --light-radius 1 --light-angle 5", "excludes"},
        {"render --light-radius -1", "--light-radius"},
        {"render --light-angle 90", "--light-angle"},
        {"render --light-position 0,0,0 --light-angle 10", "give --light-radius or --light-size instead"},
        {"render --light-shape triangle", "is not sphere, disc or rectangle"},
        {"render --light-shape disc", "give its size"},
        {"render --light-intensity 500", "with a unit"},
        {"render --light-intensity 4e38lx", "0 to 1e30"},
        {"render --light-intensity 0x10lx", "with a unit"},
        {"render --light-position 0,0,1e20", "within 1e6 world units"},
        {"render --light-intensity 500nit", "a point light has no surface"},
    };
    for (const auto& [arguments, expected] : cases) {
        const std::string shown = arguments;
        CAPTURE(shown);
        const Result r = run(arguments);
        CHECK(r.exit_code == 2);
        CAPTURE(r.err);
        CHECK(r.err.find(expected) != std::string::npos);
    }
}

TEST_CASE("I/O and data failures exit with 1 naming the file") {
    const std::string missing = temp_path("no-such-mesh.obj");
    Result r = run("render --mesh " + missing + " --out " + temp_path("x.png"));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("no-such-mesh.obj") != std::string::npos);
    const std::string broken = temp_path("broken.obj");
    std::ofstream(broken) << "v 0 0 0\nf 1 2 3\n";
    r = run("render --mesh " + broken + " --out " + temp_path("x.png"));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("broken.obj") != std::string::npos);
    r = run("render --out /proc/forbidden/x.png");
    CHECK(r.exit_code == 1);
}

TEST_CASE("a sized light is said where a technique draws it as a point, and not where it is drawn") {
    const std::string effects = FXVIEW_SOURCE_EFFECTS_DIR;
    const Result point = run("render " + effects + "/spectral/cd.fx -t Thesis --light-radius 0.5 --size 16x16 --out " + temp_path("sized.png"));
    CHECK(point.exit_code == 0);
    CHECK(point.err.find("treats the light as a point") != std::string::npos);
    const Result orders = run("render " + effects + "/spectral/cd.fx --mesh disc --light-angle 15 --size 16x16 --out " + temp_path("sized.png"));
    CHECK(orders.exit_code == 0);
    CHECK(orders.err.find("warning") == std::string::npos);
}

TEST_CASE("list --json describes debug.fx: the four debug techniques and Plain, with parameters") {
    const Result r = run(std::string("list ") + FXVIEW_SOURCE_EFFECTS_DIR + "/debug.fx --json");
    REQUIRE(r.exit_code == 0);
    const auto json = nlohmann::json::parse(r.out);
    std::vector<std::string> names;
    for (const auto& technique : json["techniques"]) names.push_back(technique["name"]);
    CHECK(names == std::vector<std::string>{"Normals", "TexCoords", "VectorToCamera", "VectorToLight", "Plain"});
    bool found_ambient = false;
    for (const auto& p : json["parameters"]) {
        if (p["name"] != "Ambient") continue;
        found_ambient = true;
        CHECK(p["type"] == "float");
        CHECK(p["default"].get<double>() == doctest::Approx(0.05));
        CHECK(p["min"].get<double>() == 0.0);
        CHECK(p["max"].get<double>() == 1.0);
        CHECK(p["group"] == "Plain");
        CHECK(p["semantic"].is_null());
    }
    CHECK(found_ambient);
}

TEST_CASE("check: the malformed corpus exits 1 with file:line messages, never a crash") {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(FXVIEW_TEST_EFFECTS) + "/malformed")) {
        if (entry.path().extension() != ".fx") continue;
        ++files;
        const std::string path = entry.path().string();
        CAPTURE(path);
        const Result r = run("check " + path);  // run() fails the test on a signal
        CHECK(r.exit_code == 1);
        const bool located = r.out.find(".fx:") != std::string::npos || r.out.find(".glsl:") != std::string::npos;
        CHECK(located);
    }
    CHECK(files >= 25);
    CHECK(run(std::string("check ") + FXVIEW_SOURCE_EFFECTS_DIR + "/debug.fx").exit_code == 0);
}

TEST_CASE("plugin: bindings checked at the declaration's line; run exits 2 for an unknown name, 1 for bad data") {
    const std::string measured = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/measured.fx";
    std::ifstream in(measured);
    const std::string source((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = source.find("\nplugin FitAshikhminShirley") + 1;  // the declaration, not a comment naming it
    REQUIRE(at != 0);
    const int line = static_cast<int>(std::count(source.begin(), source.begin() + static_cast<long>(at), '\n')) + 1;
    // Each broken binding, written into a copy of measured.fx (its includes come from effects/lib).
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"\"brdf-fit\"", "\"no-such-type\""},                        // unknown Type
        {"FitDiffuse, FitSpecular, FitExponent", "FitDiffuse, Nope, FitExponent"},  // missing target
        {"FitDiffuse, FitSpecular, FitExponent", "FitExponent, FitSpecular, FitDiffuse"},  // wrong types
        {"string Data = \"Measured\"", "string Data = \"LightIrradiance\""},  // not a sampler
        {"float Limit = 75", "float Limit = 120"},
        {"string Technique = \"Fitted\"", "string Technique = \"Nope\""}};
    const std::string copy = temp_path("test-plugin-binding.fx");
    for (const auto& [from, to] : cases) {
        std::string text = source;
        const size_t found = text.find(from, at);
        REQUIRE(found != std::string::npos);
        text.replace(found, from.size(), to);
        std::ofstream(copy) << text;
        const Result r = run("check " + copy);
        CAPTURE(to);
        CAPTURE(r.out);
        CHECK(r.exit_code == 1);
        CHECK(r.out.find("test-plugin-binding.fx:" + std::to_string(line) + ": plugin FitAshikhminShirley") != std::string::npos);
    }

    CHECK(run("check " + measured).out.find("1 plugins") != std::string::npos);
    const Result listed = run("plugin list " + measured + " --json");
    REQUIRE(listed.exit_code == 0);
    CHECK(nlohmann::json::parse(listed.out)[0]["outputs"] == nlohmann::json{"FitDiffuse", "FitSpecular", "FitExponent"});
    CHECK(run("plugin run " + measured + " Nope").exit_code == 2);
    const Result missing = run("plugin run " + measured + " FitAshikhminShirley --data " + temp_path("absent.csv"));
    CHECK(missing.exit_code == 1);
    CHECK(missing.err.find("absent.csv: no such file") != std::string::npos);

    // The plugin and the direct command solve the same problem: the same parameters.
    const std::string grid = temp_path("plugin-grid.csv"), preset = temp_path("plugin-preset.json");
    REQUIRE(run("brdf-grid --model pbr --param base=0.04 --param metallic=0 --param roughness=0.2 --out " + grid).exit_code == 0);
    const Result direct = run("fit " + grid + " --json");
    const Result plugin = run("plugin run " + measured + " FitAshikhminShirley --data " + grid + " --json --save-preset " + preset);
    REQUIRE(direct.exit_code == 0);
    REQUIRE(plugin.exit_code == 0);
    const auto d = nlohmann::json::parse(direct.out), p = nlohmann::json::parse(plugin.out);
    CHECK(p["parameters"]["FitExponent"][0] == d["ns"]);
    CHECK(p["parameters"]["FitDiffuse"] == d["cd"]);
    CHECK(p["parameters"]["FitSpecular"] == d["cs"]);
    CHECK(p["technique"] == "Fitted");
    std::ifstream saved(preset);
    const auto preset_json = nlohmann::json::parse(saved);
    CHECK(preset_json["technique"] == "Fitted");
    CHECK(preset_json["parameters"]["FitSpecular"] == d["cs"]);
}

TEST_CASE("film-fit plugin: the thickness of a film the GPU rendered comes back from its colour") {
    const std::string thinfilm = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/thinfilm.fx";
    for (const int thickness : {120, 280, 450, 600}) {
        // The GLSL FresnelExact renders the film; the plugin inverts its colour with the C++
        // transfer-matrix reflectance: two implementations. The pixel next to the sphere's centre
        // sees the film at cos θ ≈ 1 − 2e-4, which shortens the optical path by d·1e-4 < 0.1 nm;
        // 0.5 nm also covers the search's 1e-4 nm bracket and float rounding of the rendered colour.
        const Result pick = run("pick " + thinfilm + " -t FresnelExact --set Thickness=" + std::to_string(thickness) +
                                " --set Variation=0 --mesh sphere --size 64x64 --at 32,32 --json");
        REQUIRE(pick.exit_code == 0);
        const auto rgba = nlohmann::json::parse(pick.out)["rgba"];
        char target[128];
        std::snprintf(target, sizeof target, "%.9g,%.9g,%.9g", rgba[0].get<double>(), rgba[1].get<double>(), rgba[2].get<double>());
        const Result fit = run("plugin run " + thinfilm + " ThicknessFromColour --set TargetColour=" + target + " --json");
        CAPTURE(thickness);
        CAPTURE(fit.out);
        REQUIRE(fit.exit_code == 0);
        const auto result = nlohmann::json::parse(fit.out);
        CHECK(result["parameters"]["Thickness"][0].get<double>() == doctest::Approx(thickness).epsilon(0.5 / thickness));
        CHECK(result["numbers"]["delta_uv"].get<double>() < 1e-3);
        CHECK(result["converged"] == true);
    }
    // Near-white colours belong to many thicknesses (thick films wash out): all are listed.
    const Result white = run("plugin run " + thinfilm + " ThicknessFromColour --set TargetColour=1,1,1 --json");
    REQUIRE(white.exit_code == 0);
    CHECK(nlohmann::json::parse(white.out)["numbers"]["alternatives"].get<double>() >= 3);
    // A colour no film of these indices makes is reported as not reached; black has no chromaticity.
    const Result red = run("plugin run " + thinfilm + " ThicknessFromColour --set TargetColour=1,0,0 --json");
    REQUIRE(red.exit_code == 0);
    CHECK(nlohmann::json::parse(red.out)["converged"] == false);
    CHECK(run("plugin run " + thinfilm + " ThicknessFromColour --set TargetColour=0,0,0").exit_code == 2);
}

TEST_CASE("render EFFECT --technique Normals matches the built-in normal image; bad technique is exit 2") {
    const std::string effect_image = temp_path("fx-normals.pfm"), builtin_image = temp_path("builtin-normals.pfm");
    const std::string debug_fx = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/debug.fx";
    REQUIRE(run("render " + debug_fx + " --technique Normals --size 64x64 --out " + effect_image).exit_code == 0);
    REQUIRE(run("render --size 64x64 --out " + builtin_image).exit_code == 0);
    CHECK(fxview::image::read_pfm(effect_image).data == fxview::image::read_pfm(builtin_image).data);
    const Result r = run("render " + debug_fx + " --technique Nope --out " + temp_path("x.png"));
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("has no technique 'Nope'") != std::string::npos);
    CHECK(run("render " + debug_fx + " -t Plain --set Ambient=2,3 --out " + temp_path("x.png")).exit_code == 2);
    CHECK(run("render " + debug_fx + " -t Plain --set PlainColor=#ff8000 --out " + temp_path("plain.png")).exit_code == 0);
}

TEST_CASE("--save-preset then --preset reproduces the picture; a broken preset is exit 1") {
    const std::string debug_fx = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/debug.fx";
    const std::string preset = temp_path("plain.json"), first = temp_path("first.pfm"), second = temp_path("second.pfm");
    REQUIRE(run("render " + debug_fx + " -t Plain --set PlainColor=0.2,0.4,0.6 --set Ambient=0.3 --size 32x32 --save-preset " +
                preset + " --out " + first).exit_code == 0);
    REQUIRE(run("render " + debug_fx + " -t Plain --preset " + preset + " --size 32x32 --out " + second).exit_code == 0);
    CHECK(fxview::image::read_pfm(first).data == fxview::image::read_pfm(second).data);
    const auto json = nlohmann::json::parse(std::ifstream(preset));
    CHECK(json["parameters"]["Ambient"].get<double>() == doctest::Approx(0.3));
    std::ofstream(temp_path("broken.json")) << "[1, 2";
    const Result r = run("render " + debug_fx + " --preset " + temp_path("broken.json") + " --out " + temp_path("x.png"));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("broken.json") != std::string::npos);
}

TEST_CASE("every shipped effect passes check and renders") {
    int effects = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(FXVIEW_SOURCE_EFFECTS_DIR)) {
        if (entry.path().extension() != ".fx") continue;
        ++effects;
        const std::string path = entry.path().string();
        CAPTURE(path);
        const Result check = run("check " + path);
        CHECK(check.exit_code == 0);
        const Result list = run("list --json " + path);
        REQUIRE(list.exit_code == 0);
        const auto listed = nlohmann::json::parse(list.out);  // kept alive: the loop walks into it (ASan found this)
        for (const auto& technique : listed["techniques"]) {
            const std::string name = technique["name"];
            CAPTURE(name);
            const Result render = run("render " + path + " -t " + name + " --size 48x48 --out " + temp_path("shipped.png"));
            CHECK(render.exit_code == 0);
        }
    }
    CHECK(effects >= 2);
}

TEST_CASE("spectra xyz gives the published chromaticities; list, pack, cmf and plot write their outputs") {
    // Published CIE values; tolerance as in test_spectral (1.5e-4: 5 nm -> 1 nm resampling + rounding).
    const std::tuple<const char*, const char*, double, double> cases[] = {
        {"D65", "1931", 0.3127, 0.3290}, {"A", "1931", 0.4476, 0.4074}, {"E", "1931", 1.0 / 3, 1.0 / 3}, {"D65", "1964", 0.3138, 0.3310}};
    for (const auto& entry : cases) {
        const auto [name, observer, x, y] = entry;
        const std::string shown = name;
        CAPTURE(shown);
        const Result r = run(std::string("spectra xyz ") + name + " --observer " + observer + " --json");
        REQUIRE(r.exit_code == 0);
        const auto json = nlohmann::json::parse(r.out);
        CHECK(std::abs(json["xy"][0].get<double>() - x) < 1.5e-4);
        CHECK(std::abs(json["xy"][1].get<double>() - y) < 1.5e-4);
    }
    const auto list = nlohmann::json::parse(run("spectra list --json").out);
    CHECK(list["spectra"][5]["name"] == "D65");
    CHECK(run("spectra pack --format 32F --out " + temp_path("packed.exr")).exit_code == 0);
    CHECK(fxview::image::read_float_image(temp_path("packed.exr")).width == 1024);
    CHECK(run("spectra cmf --format 8 --out " + temp_path("cmf.png")).exit_code == 0);
    CHECK(run("spectra plot D65 A TCS05 --out " + temp_path("plot.png")).exit_code == 0);
    CHECK(std::filesystem::file_size(temp_path("plot.png")) > 1000);
    CHECK(run("spectra xyz NoSuchSpectrum").exit_code == 2);
    CHECK(run("spectra pack --format 12 --out x.png").exit_code == 2);
    CHECK(run("spectra pack --format 8 --out " + temp_path("wrong.exr")).exit_code == 2);
    std::ofstream(temp_path("broken.csv")) << "400,1\n390,2\n";
    const Result broken = run("spectra xyz " + temp_path("broken.csv"));
    CHECK(broken.exit_code == 1);
    CHECK(broken.err.find("broken.csv:2") != std::string::npos);
}

TEST_CASE("compare --json: pass with error figures, exit 1 for a CPU-only change or no reference") {
    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/wavelength.fx";
    const std::string heatmap = temp_path("heat.png");
    const Result ok = run("compare " + effect + " -t Blinn --size 96x96 --json --heatmap " + heatmap);
    REQUIRE(ok.exit_code == 0);
    const auto json = nlohmann::json::parse(ok.out);
    for (const char* key : {"technique", "pixels", "max_abs_error", "mean_abs_error", "worst_pixel", "mismatched_8bit", "tolerance", "pass"})
        CHECK(json.contains(key));
    CHECK(json["pass"] == true);
    CHECK(json["pixels"].get<int>() > 1000);
    CHECK(std::filesystem::exists(temp_path("heat-Blinn.png")));
    const Result wrong = run("compare " + effect + " -t Blinn --size 96x96 --json --reference-set Power=8 --heatmap " + heatmap);
    CHECK(wrong.exit_code == 1);
    CHECK(nlohmann::json::parse(wrong.out)["pass"] == false);
    const Result none = run("compare " + std::string(FXVIEW_TEST_EFFECTS) + "/valid/multipass.fx --json --heatmap " + heatmap);
    CHECK(none.exit_code == 1);
    CHECK(nlohmann::json::parse(none.out)["reference"] == false);
    CHECK(run("compare --size 32x32").exit_code == 2);  // no effect
}

TEST_CASE("bench prints one JSON line per technique with positive frame times") {
    const Result r = run(std::string("bench ") + FXVIEW_SOURCE_EFFECTS_DIR + "/debug.fx --size 32x32 --frames 2 --json");
    REQUIRE(r.exit_code == 0);
    std::istringstream lines(r.out);
    int count = 0;
    for (std::string line; std::getline(lines, line);) {
        const auto json = nlohmann::json::parse(line);
        CHECK(json["wall_ms_median"].get<double>() > 0.0);
        // A software rasteriser's timer query covers command submission only: no figure rather than a misleading one.
        const bool software = json["renderer"].get<std::string>().find("llvmpipe") != std::string::npos;
        CHECK(json["gpu_ms_median"].is_null() == software);
        ++count;
    }
    CHECK(count == 5);
    CHECK(run("bench --size 32x32").exit_code == 2);  // needs an effect
}

TEST_CASE("spectra lod: nine levels, no error at level 9, bad input exits 2") {
    const Result r = run("spectra lod TCS09 --json");
    REQUIRE(r.exit_code == 0);
    std::vector<nlohmann::json> levels;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) levels.push_back(nlohmann::json::parse(line));
    REQUIRE(levels.size() == 9);
    CHECK(levels.front()["level"] == 9);
    CHECK(levels.front()["delta_e_ab"].get<double>() == 0.0);
    CHECK(levels.front()["support_points"] == 471);
    CHECK(levels.back()["support_points"] == 3);
    // Coarser support points drift further from the full sum (levels 9..4, a smooth reflectance).
    for (size_t i = 1; i < 6; ++i) CHECK(levels[i]["delta_e_ab"].get<double>() > levels[i - 1]["delta_e_ab"].get<double>());
    CHECK(run("spectra lod --film 400").exit_code == 0);
    CHECK(run("spectra lod TCS09 --film 400").exit_code == 2);
    CHECK(run("spectra lod").exit_code == 2);
    CHECK(run("spectra lod TCS09 --lower 300").exit_code == 2);
}

TEST_CASE("spectra film-error: the Fourier series of a film approaches the 1 nm integral as the order grows") {
    const Result r = run("spectra film-error --thickness-step 250 --angle-step 40 --orders 1,3,16 --json");
    REQUIRE(r.exit_code == 0);
    const auto rows = nlohmann::json::parse(r.out)["orders"];
    REQUIRE(rows.size() == 8);  // (3 orders + the techniques' rule) x dielectric, metal
    for (size_t kind = 0; kind < 2; ++kind) {
        const std::string band = "d <= 1000 nm, angle <= 80";
        const double m1 = rows[kind * 4]["d <= 1000 nm, angle <= 80"]["mean"], m3 = rows[kind * 4 + 1][band]["mean"],
                     m16 = rows[kind * 4 + 2][band]["mean"];
        // The techniques' rule (table, at most 16 terms, exact fallback) keeps every case of this band
        // within one ΔE unit: docs/thin-films.md measures 0.52 at most on the full grid.
        CHECK(rows[kind * 4 + 3]["order"] == "technique");
        CHECK(rows[kind * 4 + 3][band]["max"].get<double>() < 1.0);
        CHECK(rows[kind * 4 + 3]["d <= 1000 nm, angle > 80"]["max"].get<double>() < 1.0);
        CAPTURE(kind);
        CHECK(m1 > m3);
        CHECK(m3 > m16);
        // The series is exact in the limit (tests/test_optics.cpp): at order 16 only slowly converging
        // strong reflections (near grazing, |x| -> 1) are left, on average far below one ΔE unit.
        CHECK(m16 < 0.05);
    }
    CHECK(run("spectra film-error --orders 99").exit_code == 2);
    CHECK(run("spectra film-error --light NoSuchLight").exit_code == 2);
}

TEST_CASE("a preset without an effect on the command line renders the preset's effect, never the debug view silently") {
    // An outside check: `render --preset gold.json` drew the debug normals and exited 0.
    const std::string preset = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/presets/gold.json";
    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx";
    const Result alone = run("pick --preset " + preset + " --size 32x32 --at 16,16 --json");
    const Result named = run("pick " + effect + " --preset " + preset + " --size 32x32 --at 16,16 --json");
    REQUIRE(alone.exit_code == 0);
    REQUIRE(named.exit_code == 0);
    CHECK(nlohmann::json::parse(alone.out)["rgba"] == nlohmann::json::parse(named.out)["rgba"]);
    const std::string missing = temp_path("preset-missing-effect.json");
    std::ofstream(missing) << "{\n  \"effect\": \"nowhere.fx\"\n}\n";
    const Result bad = run("render --preset " + missing + " --size 8x8 --out " + temp_path("never.png"));
    CHECK(bad.exit_code == 1);
    CHECK(bad.err.find("preset-missing-effect.json:2: the preset's effect 'nowhere.fx' is not found") != std::string::npos);
}
