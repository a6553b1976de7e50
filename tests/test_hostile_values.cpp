// Hostile values and hand-offs (issue #26): parameter values from any source pass one rule (finite,
// in range, whole where integer, an index inside its table); a preset's scene reads only what its
// effect may; environments stay within the budgets; file names reach an editor only as names; no
// text of a non-effect file reaches a message; every rejection is exit 1 (file:line) or 2 (usage).
#include <doctest/doctest.h>

#include "hostile_support.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string>
#include <tuple>

using fxview::test::folder;
using fxview::test::has;
using fxview::test::kShaders;
using fxview::test::kTechnique;
using fxview::test::Result;
using fxview::test::run;
using fxview::test::write;
namespace fs = std::filesystem;

namespace {

const std::string kEffects = FXVIEW_SOURCE_EFFECTS_DIR;
const std::string kWavelength = kEffects + "/spectral/wavelength.fx";
const std::string kThinfilm = kEffects + "/spectral/thinfilm.fx";
const std::string kCd = kEffects + "/spectral/cd.fx";

}  // namespace

TEST_CASE("--set values pass one rule: finite, in the declared range, whole for ints, an index inside its list") {
    const std::string out = " --size 8x8 --out " + folder("set") + "/o.png";
    // Each of these crashed, ran without end, took gigabytes or became inf before (issue 26, item 4-5).
    for (const std::string& args : {kWavelength + " --set LightSpectrum=99999999", kWavelength + " --set LightSpectrum=-1",
                                   kWavelength + " --set ObjectSpectrum=2147483647", kCd + " --set LightSpectrum=99999999",
                                   kCd + " --technique Grating --set Tracks=2147483647", kWavelength + " --set Lower=-2147483648",
                                   kWavelength + " --set Upper=2147483647", kThinfilm + " --technique FresnelFourier --set SeriesOrder=100000000",
                                   kThinfilm + " --set Thickness=1e300", kThinfilm + " --set Thickness=-1", kCd + " --set Tracks=2.5"}) {
        CAPTURE(args);
        const Result r = run("compare " + args + " --size 8x8");
        CHECK(r.exit_code == 2);
        CHECK(has(r.err, "--set "));
    }
    const Result index = run("render " + kWavelength + " --set LightSpectrum=99999999" + out);
    CHECK(has(index.err, "LightSpectrum = 99999999 is not an entry of its list"));
    const Result range = run("render " + kThinfilm + " --set Thickness=1e300" + out);
    CHECK(has(range.err, "Thickness = 1e+300 lies outside its range 0..2000"));
    CHECK(run("render " + kThinfilm + " --set Thickness=2000" + out).exit_code == 0);  // the ends are inside
}

TEST_CASE("preset values pass the same rule, with the preset's file:line") {
    const std::string dir = folder("preset-values");
    const std::string out = " --size 8x8 --out " + dir + "/o.png";
    const auto preset = [&](const std::string& name, const std::string& parameters) {
        return write(dir + "/" + name + ".json", "{\n  \"parameters\": {\n    " + parameters + "\n  }\n}\n");
    };
    for (const auto& [name, entry, reason] : std::initializer_list<std::tuple<std::string, std::string, std::string>>{
             {"index", "\"LightSpectrum\": 99999", "is not an entry of its list"},
             {"huge-int", "\"Lower\": 1e15", "whole numbers of a 32-bit int"},
             {"fraction", "\"Lower\": 400.5", "whole numbers of a 32-bit int"},
             {"range", "\"Upper\": 5000", "lies outside its range 360..830"}}) {
        CAPTURE(name);
        const Result r = run("render " + kWavelength + " --preset " + preset(name, entry) + out);
        CHECK(r.exit_code == 1);
        CHECK(has(r.err, name + ".json:3: preset value: "));
        CHECK(has(r.err, reason));
    }
    // The scene block: numbers are checked as numbers, not after a conversion that wraps or overflows.
    const std::string scene = write(dir + "/samples.json", "{\n \"parameters\": {},\n \"scene\": {\n  \"samples\": 4294967300\n }\n}\n");
    const Result samples = run("render " + kWavelength + " --preset " + scene + out);
    CHECK(samples.exit_code == 1);
    CHECK(has(samples.err, "samples.json:4: scene \"samples\" must be an integer 0-32"));
    const std::string exposure = write(dir + "/exposure.json", "{\n \"parameters\": {},\n \"scene\": {\n  \"exposure\": 1e300\n }\n}\n");
    CHECK(has(run("render " + kWavelength + " --preset " + exposure + out).err, "exposure.json:4: scene \"exposure\""));
    // A bad tone map name is the preset's error, not the command line's.
    const std::string tone = write(dir + "/tone.json", "{\n \"parameters\": {},\n \"scene\": {\n\n  \"tone_map\": \"sepia\"\n }\n}\n");
    const Result t = run("render " + kWavelength + " --preset " + tone + out);
    CHECK(t.exit_code == 1);
    CHECK(has(t.err, "tone.json:5: "));
    CHECK(!has(t.err, "--tone-map"));
}

TEST_CASE("a preset's environment reads only what its effect may, relative to the preset") {
    const std::string dir = folder("preset-environment"), outside = folder("preset-environment-outside");
    const std::string out = " --size 8x8 --out " + dir + "/o.png";
    // An equirectangular image (width twice the height) to light with.
    REQUIRE(run("render --mesh sphere --size 16x8 --out " + outside + "/secret.png").exit_code == 0);
    fs::copy_file(outside + "/secret.png", dir + "/room.png");
    const std::string effect = kEffects + "/brdf/analytic.fx";
    const std::string absolute = write(dir + "/absolute.json", "{\n \"parameters\": {},\n \"scene\": {\n  \"environment\": \"" + outside + "/secret.png\"\n }\n}\n");
    const Result refused = run("render " + effect + " --preset " + absolute + out);
    CHECK(refused.exit_code == 1);
    CHECK(has(refused.err, "absolute.json:4: environment"));
    CHECK(has(refused.err, "refused by the file-access policy"));
    const std::string six = write(dir + "/six.json", "{\n \"parameters\": {},\n \"scene\": {\n  \"environment\": \"room.png,room.png,room.png,room.png,room.png,../preset-environment-outside/secret.png\"\n }\n}\n");
    CHECK(has(run("render " + effect + " --preset " + six + out).err, "refused by the file-access policy"));
    // --allow-path lets it in, as for textures.
    CHECK(run("render " + effect + " --preset " + absolute + " --allow-path " + outside + out).exit_code == 0);
    // A relative name resolves from the preset's folder, whatever the working directory.
    const std::string relative = write(dir + "/relative.json", "{\n \"parameters\": {},\n \"scene\": {\n  \"environment\": \"room.png\"\n }\n}\n");
    CHECK(run("render " + effect + " --preset " + relative + out).exit_code == 0);
    // A 1 MB environment string is refused before anything splits or reads it.
    const std::string longer = write(dir + "/long.json", "{\n \"parameters\": {},\n \"scene\": {\n  \"environment\": \"" + std::string(1 << 20, 'a') + "\"\n }\n}\n");
    const Result too_long = run("render " + effect + " --preset " + longer + out);
    CHECK(too_long.exit_code == 1);
    CHECK(has(too_long.err, "long.json:4: scene \"environment\" is 1048576 characters long"));
    // Unknown keys of the scene block are named at their line.
    const std::string unknown = write(dir + "/unknown.json", "{\n \"parameters\": {},\n \"scene\": {\n  \"enviroment\": \"studio\"\n }\n}\n");
    CHECK(has(run("render " + effect + " --preset " + unknown + out).err, "unknown.json:4: unknown scene setting \"enviroment\""));
}

TEST_CASE("environments are read within the budgets: six faces count together, as the float radiance they become") {
    const std::string dir = folder("environment-budget");
    REQUIRE(run("render --mesh sphere --size 256x256 --out " + dir + "/face.png").exit_code == 0);
    std::string faces;
    for (int i = 0; i < 6; ++i) faces += (i ? "," : "") + dir + "/face.png";
    // 256 x 256 x 16 bytes = 1 MiB of float radiance per face: the second face passes a 1.5 MiB budget.
    const std::string effect = kEffects + "/brdf/analytic.fx";
    const Result r = run("render " + effect + " --environment " + faces + " --limit texture-bytes=1572864 --size 8x8 --out " + dir + "/o.png");
    CHECK(r.exit_code == 1);
    CHECK(has(r.err, "the environment's float radiance 2097152 exceeds the budget texture-bytes"));
    CHECK(run("render " + effect + " --environment " + faces + " --size 8x8 --out " + dir + "/o.png").exit_code == 0);
    // Without an effect the environment is the background: a missing one is an error, not ignored.
    const Result missing = run("render --environment " + dir + "/missing.hdr --size 8x8 --out " + dir + "/o.png");
    CHECK(missing.exit_code == 1);
    CHECK(has(missing.err, "missing.hdr: no such file"));
    const Result device = run("render --environment /dev/zero --size 8x8 --out " + dir + "/o.png");
    CHECK(device.exit_code == 1);
    CHECK(has(device.err, "/dev/zero: not a regular file"));
}

TEST_CASE("an effect includes only shader sources: a .env next to it never reaches a compiler message") {
    const std::string dir = folder("include-secret");
    write(dir + "/keys.env", "SECRET_TOKEN_4711 = 1;\n");
    const std::string effect = write(dir + "/e.fx", "#include \"keys.env\"\n" + kShaders + kTechnique);
    const Result r = run("check " + effect);
    CHECK(r.exit_code == 1);
    CHECK(has(r.out, "e.fx:1: included file 'keys.env' is not a shader source"));
    CHECK(!has(r.err + r.out, "SECRET_TOKEN_4711"));
}

TEST_CASE("a .brdf line of 30 000 blanks is scanned, not matched by a recursive regex") {
    const std::string dir = folder("brdf-blanks");
    const std::string brdf = write(dir + "/blanks.brdf", "analytic\n::begin shader\n" + std::string(30000, ' ') +
                                                             "vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(1.0); }\n" +
                                                             std::string(30000, ' ') + "\n::end shader\n");
    const Result r = run("check " + brdf);
    CHECK(r.exit_code == 0);
}

TEST_CASE("plugin declarations: misspelt annotations, twice-named targets and unbounded ranges are errors at their line") {
    const std::string dir = folder("plugins");
    // The shipped effect with one more plugin declared at its end.
    const auto with_plugin = [&](const std::string& effect, const std::string& name, const std::string& extra) {
        std::ifstream in(effect);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        return write(dir + "/" + name + ".fx", text + "\n" + extra + "\n");
    };
    const auto declare = [&](const std::string& name, const std::string& plugin) { return with_plugin(kEffects + "/brdf/analytic.fx", name, plugin); };
    const Result misspelt = run("check " + declare("misspelt", "plugin P < string Type = \"brdf-fit\"; string DataFile = \"x.csv\"; string Modle = \"ggx\"; >;"));
    CHECK(misspelt.exit_code == 1);
    CHECK(has(misspelt.out, "unknown annotation 'Modle'"));
    const Result twice = run("check " + declare("twice", "plugin P < string Type = \"brdf-fit\"; string DataFile = \"x.csv\"; string Model = \"ggx\";"
                                                         " string Targets = \"GGXDiffuse, GGXDiffuse, GGXAlpha\"; >;"));
    CHECK(twice.exit_code == 1);
    CHECK(has(twice.out, "Targets names GGXDiffuse twice"));
    const std::string film = with_plugin(kThinfilm, "film",
                                         "uniform float Wide < float UIMin = 0; float UIMax = 1e30; > = 1;\n"
                                         "plugin Q < string Type = \"film-fit\"; string Target = \"TargetColour\"; string Vary = \"Wide\";"
                                         " string OuterIndex = \"OuterIndex\"; string FilmIndex = \"FilmIndex\"; string SubstrateIndex = \"SubstrateIndex\"; >;");
    const Result wide = run("check " + film);
    CHECK(wide.exit_code == 1);
    CHECK(has(wide.out, "spans more than 20 000 nm"));
}

TEST_CASE("nonsense numbers on the command line are usage errors: NaN passes no range") {
    const std::string dir = folder("cli-numbers");
    REQUIRE(run("brdf-grid --model pbr --samples 4 4 4 --out " + dir + "/g.csv").exit_code == 0);
    for (const char* brighten : {"nan", "0", "-1", "inf"}) {
        CAPTURE(brighten);
        CHECK(run("fit " + dir + "/g.csv --preview " + dir + "/p.png --brighten " + brighten).exit_code == 2);
    }
    CHECK(run("render --mesh sphere --fov nan --size 8x8 --out " + dir + "/o.png").exit_code == 2);
    CHECK(run("render --mesh sphere --camera-distance nan --size 8x8 --out " + dir + "/o.png").exit_code == 2);
}

TEST_CASE("negative samples of a grid are left out and counted, as MERL's are") {
    const std::string dir = folder("negative-grid");
    REQUIRE(run("brdf-grid --model pbr --samples 7 7 7 --out " + dir + "/g.csv").exit_code == 0);
    std::ifstream in(dir + "/g.csv");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // The red value of a row in the middle of the grid (light and camera inside the limit) made negative.
    size_t row = 0;
    for (int i = 0; i < 2 + 3 * 49 + 7 * 2 + 3; ++i) row = text.find('\n', row) + 1;
    size_t red = row;
    for (int i = 0; i < 3; ++i) red = text.find(',', red) + 1;
    text.replace(red, text.find(',', red) - red, "-0.5");
    write(dir + "/negative.csv", text);
    const Result r = run("fit " + dir + "/negative.csv");
    CHECK(has(r.err, "1 of "));
    CHECK(has(r.err, "are negative (unmeasured)"));
}

TEST_CASE("docs/preset.schema.json and fxview agree: every scene key it lists loads, a key it does not is refused") {
    const std::string dir = folder("schema");
    std::ifstream in(kEffects + "/../docs/preset.schema.json");
    const nlohmann::json schema = nlohmann::json::parse(in);
    const nlohmann::json& scene = schema["properties"]["scene"]["properties"];
    REQUIRE(scene.size() == 8);
    const std::string effect = kEffects + "/brdf/analytic.fx";
    for (const auto& [key, rule] : scene.items()) {
        // A valid value from the schema itself: its first enum entry, its minimum, or a built-in name.
        const nlohmann::json value = rule.contains("enum") ? rule["enum"][0] : rule.contains("minimum") ? rule["minimum"] : nlohmann::json("studio");
        const nlohmann::json preset = {{"parameters", nlohmann::json::object()}, {"scene", {{key, value}}}};
        const std::string file = write(dir + "/" + key + ".json", preset.dump(1));
        CAPTURE(key);
        CHECK(run("check " + effect + " --preset " + file).exit_code == 0);
        if (rule.contains("maximum")) {  // one past the schema's maximum is refused by fxview too
            const nlohmann::json over = {{"parameters", nlohmann::json::object()}, {"scene", {{key, rule["maximum"].get<double>() + 1}}}};
            CHECK(run("check " + effect + " --preset " + write(dir + "/over.json", over.dump(1))).exit_code == 1);
        }
    }
    for (const auto& [key, rule] : schema["properties"].items()) CHECK((key == "effect" || key == "technique" || key == "note" || key == "$schema" || key == "parameters" || key == "scene"));
    // The shipped presets follow it.
    for (const auto& entry : fs::directory_iterator(kEffects + "/brdf/presets"))
        CHECK(run("check " + effect + " --preset " + entry.path().string()).exit_code == 0);
    const Result extra = run("check " + effect + " --preset " + write(dir + "/extra.json", "{\n \"parameters\": {},\n \"colour\": 1\n}\n"));
    CHECK(extra.exit_code == 1);
    CHECK(has(extra.out, "extra.json:3: unknown preset key \"colour\""));
}

TEST_CASE("a copy of a shipped effect with wider ranges gets no endless CPU reference") {
    // References are found by the effect's file name: a stranger's cd.fx with Tracks up to 2^31-1
    // must not make compare run without end.
    const std::string dir = folder("reference-bounds");
    std::ifstream in(kCd);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = text.find("int UIMax = 200;");
    REQUIRE(at != std::string::npos);
    text.replace(at, 16, "int UIMax = 2147483647;");
    const std::string copy = write(dir + "/cd.fx", text);
    const Result r = run("compare " + copy + " --technique Grating --set Tracks=100000 --mesh disc --camera-rotate 50,0,0 --size 16x16");
    CHECK(r.exit_code == 1);
    CHECK(has(r.err, "Tracks = 100000 lies outside what the CPU reference computes (1..200)"));
}

TEST_CASE("a copy of any shipped effect in another folder still opens: its headers live in effects/lib") {
    // Users copy a shipped effect to tweak it; an include kept next to the original would break
    // the copy (it did once for cd.fx's orders). Every .fx and .cgfx is copied alone and checked.
    const std::string dir = folder("lone-copies");
    int copies = 0;
    for (const auto& entry : fs::recursive_directory_iterator(kEffects)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".fx" && ext != ".cgfx") continue;
        const std::string copy = dir + "/" + entry.path().filename().string();
        fs::copy_file(entry.path(), copy, fs::copy_options::overwrite_existing);
        const Result r = run("check " + copy);
        INFO(copy, "\n", r.out, r.err);
        CHECK(r.exit_code == 0);
        ++copies;
    }
    CHECK(copies >= 9);  // the nine shipped effects (a rename that hid them all would pass vacuously)
}
