// The interactive viewer in a real window under xvfb-run (CTest wraps this binary): a window
// screenshot shows the parameter panel and the object; a script changes a parameter and turns the
// light and the picture follows; a pick through the UI equals `fxview pick`; every shipped effect
// runs a few frames without crashing; broken scripts are refused with file:line.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <fstream>
#include <sys/wait.h>
#include <thread>
#include <set>
#include <sstream>

#include "image/image_file.hpp"
#include "test_support.hpp"
#include "texture/texture_file.hpp"
#ifdef FXVIEW_HAVE_XTEST
#include "x_input.hpp"
#endif

using fxview::test::Result;
using fxview::test::run;
using fxview::test::temp_path;

namespace {

const std::string kDebugFx = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/debug.fx";

fxview::texture::TextureData load_png(const std::string& path) { return fxview::texture::load_texture_file(path); }

std::array<float, 4> texel(const fxview::texture::TextureData& t, int x, int y) {
    std::array<float, 4> rgba{};
    fxview::texture::read_texel(t, 0, 0, x, y, rgba.data());
    return rgba;
}

// Distinct colours in a region: a blank (cleared) region has one or two.
size_t distinct_colours(const fxview::texture::TextureData& t, int x0, int y0, int x1, int y1) {
    std::set<std::uint32_t> colours;
    for (int y = y0; y < y1; y += 2)
        for (int x = x0; x < x1; x += 2) {
            const auto& bytes = t.faces[0][0].bytes;
            const size_t i = (static_cast<size_t>(y) * t.width() + x) * 4;
            colours.insert(bytes[i] | bytes[i + 1] << 8 | bytes[i + 2] << 16);
        }
    return colours.size();
}

// The JSON lines a script printed, in order.
std::vector<nlohmann::json> json_lines(const std::string& out) {
    std::vector<nlohmann::json> lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line.front() == '{') lines.push_back(nlohmann::json::parse(line));
    return lines;
}

}  // namespace

TEST_CASE("--frames 30 --screenshot saves a window with the parameter panel and the rendered object") {
    const std::string shot = temp_path("window.png");
    const Result r = run("view " + kDebugFx + " --window 1024x640 --frames 30 --screenshot " + shot);
    REQUIRE(r.exit_code == 0);
    const auto window = load_png(shot);
    CHECK(window.width() == 1024);
    CHECK(window.height() == 640);
    // The panel (left 40%) holds text and widgets: many colours, not a blank area.
    CHECK(distinct_colours(window, 0, 0, 400, 300) > 8);
    // The render view's centre shows the sphere's facing normal: blue channel high, not background grey.
    const auto centre = texel(window, 409 + (1024 - 409) / 2, 320);
    CHECK(centre[2] > 0.9f);
    CHECK(centre[0] > 0.6f);
}

TEST_CASE("a script changes a parameter and turns the light; the picture follows, picks agree with fxview pick") {
    const std::string script = temp_path("viewer-script.txt");
    const std::string before = temp_path("before.png"), after = temp_path("after.png"), turned = temp_path("turned.png");
    std::ofstream(script) << "technique Plain\n"
                             "render-screenshot " << before << "\n"
                             "set PlainColor 1,0.2,0.1\n"
                             "pick 64 64\n"
                             "render-screenshot " << after << "\n"
                             "rotate light 0 90 0\n"
                             "render-screenshot " << turned << "\n";
    // Without MSAA, as pick renders: a resolve of four equal samples may round the last bit.
    const Result r = run("view " + kDebugFx + " --render-size 128x128 --samples 0 --script " + script + " --frames 2");
    REQUIRE(r.exit_code == 0);
    const auto grey = load_png(before), red = load_png(after), dark = load_png(turned);
    const auto a = texel(grey, 64, 64), b = texel(red, 64, 64), c = texel(dark, 64, 64);
    CHECK(std::abs(a[0] - a[1]) < 0.01f);  // grey Plain colour (0.8, 0.8, 0.8)
    CHECK(b[0] > b[1] + 0.2f);             // now red-orange
    CHECK(c[0] < b[0] - 0.2f);             // the light turned away: only ambient is left
    CHECK(texel(red, 2, 2)[0] == texel(grey, 2, 2)[0]);  // background unchanged

    // The UI pick printed by the script equals the headless pick of the same scene.
    const auto ui_pick = nlohmann::json::parse(r.out.substr(0, r.out.find('\n')));
    const Result cli = run("pick " + kDebugFx + " -t Plain --set PlainColor=1,0.2,0.1 --size 128x128 --at 64,64 --json");
    REQUIRE(cli.exit_code == 0);
    const auto cli_pick = nlohmann::json::parse(cli.out);
    CHECK(ui_pick["rgba"] == cli_pick["rgba"]);
    CHECK(ui_pick["rgba8"] == cli_pick["rgba8"]);
    CHECK(ui_pick["packed"] == cli_pick["packed"]);
}

TEST_CASE("every shipped effect runs a few frames in the viewer without crashing") {
    int effects = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(FXVIEW_SOURCE_EFFECTS_DIR)) {
        if (entry.path().extension() != ".fx") continue;
        ++effects;
        CAPTURE(entry.path().string());
        const Result r = run("view " + entry.path().string() + " --window 640x400 --frames 5");
        CHECK(r.exit_code == 0);
    }
    CHECK(effects >= 3);
}

TEST_CASE("an effect that fails at start is watched: fixing the file opens it") {
    const std::string effect = temp_path("viewer-watch/broken.fx"), script = temp_path("viewer-watch.txt");
    std::filesystem::create_directories(std::filesystem::path(effect).parent_path());
    const std::string good = "GLSLShader VS { in vec3 position; void main() { gl_Position = vec4(position, 1.0); } }\n"
                             "GLSLShader FS { out vec4 color; void main() { color = vec4(1.0); } }\n"
                             "technique T { pass P { VertexShader = VS; FragmentShader = FS; } }\n";
    std::ofstream(effect) << "technique T { pass P { VertexShader = VS; FragmentShader = Missing; } }\n";
    std::ofstream(script) << "wait-effect 60\ntechnique T\n";
    // The fix is saved while the viewer runs (after it has failed once).
    std::thread fixer([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(1500));
        std::ofstream(effect) << good;
    });
    const Result r = run("view " + effect + " --render-size 32x32 --script " + script + " --frames 2");
    fixer.join();
    CAPTURE(r.err);
    CHECK(r.exit_code == 0);  // wait-effect found the effect loaded, and `technique T` found T
}

TEST_CASE("errors are listed as file:line places that open in $VISUAL/$EDITOR at that line") {
    const std::string effect = temp_path("viewer-errors/broken.fx"), script = temp_path("viewer-errors.txt");
    const std::string editor = temp_path("viewer-errors/editor.sh"), opened = temp_path("viewer-errors/opened.txt");
    std::filesystem::create_directories(std::filesystem::path(effect).parent_path());
    std::ofstream(effect) << "// line 1\n\ntechnique T { pass P { VertexShader = VS; FragmentShader = Missing; } }\n";
    // A stand-in editor that records how it was called.
    std::ofstream(editor) << "#!/bin/sh\necho \"$@\" > " << opened << "\n";
    std::filesystem::permissions(editor, std::filesystem::perms::owner_all);
    std::filesystem::remove(opened);
    std::ofstream(script) << "open-error 1\n";
    unsetenv("VISUAL");
    setenv("EDITOR", editor.c_str(), 1);
    const Result r = run("view " + effect + " --render-size 32x32 --script " + script + " --frames 30");
    unsetenv("EDITOR");
    CAPTURE(r.err);
    CHECK(r.exit_code == 0);
    std::string line;
    for (int wait = 0; wait < 50 && line.empty(); ++wait) {  // the editor runs detached
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        std::ifstream in(opened);
        std::getline(in, line);
    }
    CHECK(line == "+3 " + effect);  // vi/emacs/nano convention: +LINE FILE, at the technique's line
}

TEST_CASE("the texture inspector opens on a texture by script; an unknown texture or channel is named") {
    const std::string textured = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/examples/textured.fx", script = temp_path("inspect.txt");
    for (const char* line : {"inspect-texture Checker g 2", "inspect-texture SkyTexture", "inspect-texture Checker a -1"}) {
        std::ofstream(script) << line << "\nframes 3\n";
        const Result r = run("view " + textured + " --render-size 32x32 --script " + script + " --frames 2");
        CAPTURE(line);
        CAPTURE(r.err);
        CHECK(r.exit_code == 0);
    }
    std::ofstream(script) << "inspect-texture Nothing\n";
    const Result missing = run("view " + textured + " --render-size 32x32 --script " + script + " --frames 2");
    CHECK(missing.exit_code == 1);
    CHECK(missing.err.find("no texture 'Nothing'") != std::string::npos);
    std::ofstream(script) << "inspect-texture Checker q\n";
    const Result channel = run("view " + textured + " --render-size 32x32 --script " + script + " --frames 2");
    CHECK(channel.exit_code == 1);
    CHECK(channel.err.find("channel rgba, r, g, b or a") != std::string::npos);
}

TEST_CASE("the texture inspector shows a 2D texture upright, with the mip levels GL generated for a PNG") {
    // A tall 4x8 PNG: its first row red, its last row blue, green between (0 and 1 are exact in sRGB).
    fxview::image::FloatImage picture(4, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 4; ++x) {
            float* p = picture.pixel(x, y);
            p[0] = y == 0, p[1] = y > 0 && y < 7, p[2] = y == 7, p[3] = 1;
        }
    const std::string png = temp_path("inspector-rows.png"), script = temp_path("inspector-rows.txt");
    fxview::image::write_png(png, picture, fxview::image::Encoding::Srgb);
    std::ofstream(script) << "inspect-texture Checker\ninspect-texel 0.5 0.01\ninspect-texel 0.5 0.99\n"
                             "inspect-texture Checker rgba 0 1\ninspect-texel 0.5 0.5\n";
    const std::string textured = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/examples/textured.fx";
    const Result r = run("view " + textured + " --set Checker=" + png + " --render-size 32x32 --script " + script + " --frames 2");
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    std::istringstream lines(r.out);
    std::string top, bottom, level1;
    std::getline(lines, top);
    std::getline(lines, bottom);
    std::getline(lines, level1);
    const auto t = nlohmann::json::parse(top), b = nlohmann::json::parse(bottom), l = nlohmann::json::parse(level1);
    // The preview's top shows the file's first row (red), which GL stores as its last row (7).
    CHECK(t["texel"][1] == 7);
    CHECK(t["value"] == nlohmann::json({1.0, 0.0, 0.0, 1.0}));
    CHECK(b["texel"][1] == 0);
    CHECK(b["value"] == nlohmann::json({0.0, 0.0, 1.0, 1.0}));
    // One level in the file, 4 in GL (8, 4, 2, 1 rows): the mip slider has them.
    CHECK(t["levels"] == 4);
    CHECK(t["generated_levels"] == true);
    CHECK(l["level"] == 1);
    CHECK(l["texel"][1].get<int>() >= 0);
    CHECK(l["texel"][1].get<int>() < 4);
}

TEST_CASE("view takes render's options: --size, --samples and --debug-view give render's image") {
    const std::string shot = temp_path("view-options.png"), rendered = temp_path("render-options.png");
    const std::string options = " --debug-view uv --size 64x48 --samples 4";
    REQUIRE(run("view" + options + " --frames 2 --render-screenshot " + shot).exit_code == 0);
    REQUIRE(run("render" + options + " --out " + rendered).exit_code == 0);
    const auto view = load_png(shot), render = load_png(rendered);
    REQUIRE(view.width() == 64);
    REQUIRE(view.height() == 48);
    // The same scene, debug shader and MSAA: the same 8-bit pixels up to one code value (the
    // window's multisample resolve and the offscreen one may round differently at edges).
    for (const auto& [x, y] : {std::pair{32, 24}, std::pair{20, 20}, std::pair{44, 30}})
        for (int c = 0; c < 4; ++c) CHECK(std::abs(texel(view, x, y)[c] - texel(render, x, y)[c]) <= 1.0f / 255.0f + 1e-6f);
    // Save screenshot gives what the view shows: uncovered pixels on the view's opaque grey backdrop
    // (linear 0.02, sRGB 39/255), not transparent.
    const std::string saved = temp_path("view-saved.png"), script = temp_path("view-saved.txt");
    std::ofstream(script) << "save-screenshot " << saved << "\n";
    REQUIRE(run("view" + options + " --script " + script + " --frames 2").exit_code == 0);
    const auto backdrop = load_png(saved);
    CHECK(texel(backdrop, 0, 0)[3] == 1.0f);
    CHECK(std::abs(texel(backdrop, 0, 0)[0] - 39.0f / 255.0f) <= 1.0f / 255.0f);
    CHECK(texel(backdrop, 32, 24) == texel(view, 32, 24));  // the object itself is as rendered
    CHECK(run("view --backend osmesa --frames 1").exit_code == 2);  // a window has no backend choice
    CHECK(run("view --samples 3 --frames 1").exit_code == 2);
}

TEST_CASE("broken scripts and options are refused with exit 2") {
    const std::string script = temp_path("bad-script.txt");
    std::ofstream(script) << "set PlainColor 1,0,0\nfly away\n";
    const Result r = run("view " + kDebugFx + " --script " + script + " --frames 1");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("bad-script.txt:2: unknown script action 'fly'") != std::string::npos);
    CHECK(run("view " + kDebugFx + " --screenshot x.png").exit_code == 2);  // needs --frames
}

TEST_CASE("script values pass the rule of every value: a refused one is named and the run goes on") {
    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/wavelength.fx", script = temp_path("bad-values.txt");
    std::ofstream(script) << "set LightSpectrum 99999\nset Lower 2.5\nset Kd 0.5\n";
    const Result r = run("view " + effect + " --render-size 32x32 --script " + script + " --frames 2");
    CAPTURE(r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("LightSpectrum = 99999 is not an entry of its list") != std::string::npos);
    CHECK(r.err.find("whole numbers of a 32-bit int, not 2.5") != std::string::npos);
}

TEST_CASE("a cube map becomes the skybox behind the objects") {
    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/examples/textured.fx";
    const std::string script = temp_path("sky-script.txt"), plain = temp_path("no-sky.png"), sky = temp_path("sky.png");
    std::ofstream(script) << "render-screenshot " << plain << "\nskybox SkyTexture\nrender-screenshot " << sky << "\nskybox Nope\n";
    const Result r = run("view " + effect + " -t Mirror --render-size 96x96 --script " + script + " --frames 2");
    CAPTURE(r.err);
    CHECK(r.exit_code == 1);  // the last line names no cube map: reported, the run goes on
    CHECK(r.err.find("no cube map texture 'Nope'") != std::string::npos);
    const auto before = load_png(plain), after = load_png(sky);
    // A corner shows the background before and the sky after; the sphere's centre stays the mirror.
    CHECK(texel(before, 1, 1)[2] < 0.1f);
    CHECK(texel(after, 1, 1)[2] > 0.3f);
    CHECK(texel(after, 48, 48) == texel(before, 48, 48));
}

TEST_CASE("the Plugins tab's BRDF fit shows the fitted BRDF: the same pixel as fxview pick with fit's preset") {
    const std::string grid = temp_path("viewer-fit/grid.csv"), preset = temp_path("viewer-fit/preset.json");
    REQUIRE(run("brdf-grid --model ashikhmin-fit --param cd=0.3,0.1,0.1 --param cs=0.6,0.5,0.4 --param ns=30 --out " + grid).exit_code == 0);
    REQUIRE(run("fit " + grid + " --preset " + preset).exit_code == 0);
    const std::string script = temp_path("viewer-fit.txt"), broken = temp_path("viewer-fit/missing.csv");
    const std::string shot = temp_path("viewer-fit/window.png");
    std::ofstream(script) << "fit " << grid << "\npick 64 64\ntab Plugins\nscreenshot " << shot << "\n";
    const std::string analytic = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx";
    const Result r = run("view " + analytic + " --window 1024x900 --render-size 128x128 --samples 0 --script " + script + " --frames 2");
    REQUIRE(r.exit_code == 0);
    // The Fit tab shows the result and, below it, the measured | model | difference preview: the
    // lower half of the panel holds far more colours than an empty panel's few greys.
    const auto window = load_png(shot);
    CHECK(distinct_colours(window, 0, 450, 400, 900) > 50);
    std::istringstream lines(r.out);
    std::string fit_line, pick_line;
    std::getline(lines, fit_line);
    std::getline(lines, pick_line);
    const auto fitted = nlohmann::json::parse(fit_line)["plugin"];
    CHECK(fitted["name"] == "FitAshikhminShirley");
    CHECK(fitted["parameters"]["FitExponent"][0].get<double>() == doctest::Approx(30.0).epsilon(1e-6));
    const Result cli = run("pick " + analytic + " --preset " + preset + " --size 128x128 --at 64,64 --json");
    REQUIRE(cli.exit_code == 0);
    CHECK(nlohmann::json::parse(pick_line)["rgba"] == nlohmann::json::parse(cli.out)["rgba"]);

    // A missing file: the script reports it (exit 1), the viewer does not crash.
    std::ofstream(script) << "fit " << broken << "\n";
    const Result failed = run("view " + analytic + " --render-size 64x64 --script " + script + " --frames 2");
    CHECK(failed.exit_code == 1);
    CHECK(failed.err.find("missing.csv: no such file") != std::string::npos);
}

TEST_CASE("measured.fx's brdf-fit plugin gives the same parameters in the viewer as fxview plugin run") {
    const std::string measured = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/measured.fx";
    const Result cli = run("plugin run " + measured + " FitAshikhminShirley --json");
    REQUIRE(cli.exit_code == 0);
    const auto expected = nlohmann::json::parse(cli.out);
    CHECK(expected["converged"] == true);
    const std::string script = temp_path("viewer-plugin.txt");
    std::ofstream(script) << "plugin FitAshikhminShirley\n";
    const Result viewer = run("view " + measured + " --render-size 64x64 --script " + script + " --frames 2");
    REQUIRE(viewer.exit_code == 0);
    const auto got = nlohmann::json::parse(viewer.out.substr(0, viewer.out.find('\n')))["plugin"];
    // The same code on the same data and values: bit-identical numbers (JSON writes doubles exactly).
    CHECK(got["parameters"] == expected["parameters"]);
    // The plugin declares Technique = "Fitted": the objects show the fit, not the measured data.
    CHECK(nlohmann::json::parse(viewer.out.substr(0, viewer.out.find('\n')))["technique"] == "Fitted");

    // A full-density MERL file (seconds of fitting) on the worker thread: the window keeps drawing
    // frames meanwhile (at 60 FPS under Xvfb here: 258 frames in 4.3 s), and the result is the CLI's.
    const std::string merl = temp_path("viewer-plugin/gold.binary");
    REQUIRE(run("brdf-grid --model pbr --param base=0.9,0.6,0.3 --param roughness=0.3 --merl-out --out " + merl).exit_code == 0);
    const Result merl_cli = run("plugin run " + measured + " FitAshikhminShirley --set Measured=" + merl + " --json");
    REQUIRE(merl_cli.exit_code == 0);
    std::ofstream(script) << "plugin-start FitAshikhminShirley\nplugin-wait\n";
    const Result async = run("view " + measured + " --set Measured=" + merl + " --render-size 64x64 --script " + script + " --frames 2");
    REQUIRE(async.exit_code == 0);
    const auto waited = nlohmann::json::parse(async.out.substr(0, async.out.find('\n')));
    CHECK(waited["plugin"]["parameters"] == nlohmann::json::parse(merl_cli.out)["parameters"]);
    // At least 10 frames: far below what the machine draws, far above the 1-2 a blocked UI would.
    CHECK(waited["frames_while_running"].get<int>() >= 10);
    CHECK(waited["technique"] == "Fitted");  // as the Plugins tab's Run: switched when it started

    // An unknown plugin is a usage error of the script, reported with its line; the viewer goes on.
    std::ofstream(script) << "plugin Nope\n";
    const Result bad = run("view " + measured + " --render-size 64x64 --script " + script + " --frames 2");
    CHECK(bad.exit_code != 0);
    CHECK(bad.err.find("no plugin 'Nope'") != std::string::npos);

    // Numbers in scripts are checked: a clear message naming the verb, not std::stoi's "stoi".
    std::ofstream(script) << "pick 3x 4\n";
    const Result bad_number = run("view " + measured + " --render-size 64x64 --script " + script + " --frames 2");
    CHECK(bad_number.exit_code != 0);
    CHECK(bad_number.err.find("script line 1: pick: '3x' is not a whole number") != std::string::npos);
}

TEST_CASE("an effect refused by the file-access policy opens once its folder is allowed, edits kept") {
    namespace fs = std::filesystem;
    const std::string dir = temp_path("viewer-policy"), outside = temp_path("viewer-policy-outside");
    fs::remove_all(dir);
    fs::remove_all(outside);
    fs::create_directories(dir);
    fs::create_directories(outside);
    fs::copy_file(std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/../textures/checker.png", outside + "/checker.png");
    const std::string effect = dir + "/outside.fx";
    std::ofstream(effect) << "texture Tex < string ResourceName = \"" << outside << "/checker.png\"; >;\n"
                          << "uniform sampler2D S < string Texture = \"Tex\"; >;\n"
                          << "uniform float Gain < float UIMin = 0; float UIMax = 2; > = 1.0;\n"
                          << "GLSLShader VS { in vec3 position; void main() { gl_Position = vec4(position, 1.0); } }\n"
                          << "GLSLShader FS { out vec4 color; void main() { color = Gain * texture(S, vec2(0.5)); } }\n"
                          << "technique T { pass P { VertexShader = VS; FragmentShader = FS; } }\n";
    const std::string script = temp_path("policy-script.txt");
    // Refused at start: no effect to edit. Allowed: it opens, and a set works.
    std::ofstream(script) << "set Gain 0.5\nallow-path " << outside << "\nset Gain 0.5\ntechnique T\n";
    const Result r = run("view " + effect + " --script " + script + " --frames 2");
    CAPTURE(r.err);
    CHECK(r.exit_code == 1);  // the first `set` found no effect: reported, the run goes on
    CHECK(r.err.find("script line 1: no effect loaded") != std::string::npos);
    CHECK(r.err.find("script line 3") == std::string::npos);
    CHECK(r.err.find("script line 4") == std::string::npos);
    // The same from the command line: --allow-path opens it at once.
    std::ofstream(script) << "set Gain 0.5\ntechnique T\n";
    CHECK(run("view " + effect + " --allow-path " + outside + " --script " + script + " --frames 2").exit_code == 0);
}

TEST_CASE("the BRDF tab plots a .brdf file and its check runs by script; an effect without the grid is refused") {
    const std::string lambert = std::string(FXVIEW_TEST_EFFECTS) + "/brdf/lambert.brdf", script = temp_path("brdf-tab.txt");
    std::ofstream(script) << "tab BRDF\nframes 2\nbrdf-check\n";
    const Result r = run("view " + lambert + " --render-size 32x32 --script " + script + " --frames 2");
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    const auto line = r.out.substr(r.out.find("{\"brdf_check\""));
    const auto check = nlohmann::json::parse(line.substr(0, line.find('\n')))["brdf_check"];
    // Lambert's albedo is its largest reflectance, 0.8 (as brdf-check on the command line).
    CHECK(check["max_albedo"].get<double>() == doctest::Approx(0.8).epsilon(1e-4));
    CHECK(check["conserves_energy"] == true);
    CHECK(check["energy"] == "conserves");
    // The check's 96 renders are spread over UI frames (about 30 ms of them a frame), not one long frame.
    CHECK(nlohmann::json::parse(line.substr(0, line.find('\n')))["frames_while_checking"].get<int>() > 3);
    // Every view draws, and kept curves accumulate across parameter changes for the overlay.
    std::ofstream(script) << "brdf-view lobe\nbrdf-view slice\nbrdf-view sphere\nbrdf-view polar\nbrdf-keep\nset reflectance 0.3,0.3,0.3\nbrdf-keep\nframes 2\n";
    const Result views = run("view " + lambert + " --render-size 32x32 --script " + script + " --frames 2");
    CAPTURE(views.err);
    CHECK(views.exit_code == 0);
    for (const char* view : {"lobe", "slice", "sphere", "polar"}) CHECK(views.out.find("\"brdf_view\":\"" + std::string(view) + "\"") != std::string::npos);
    CHECK(views.out.find("white: f = 0.159") != std::string::npos);  // the slice of this Lambert: green 0.5 / pi everywhere
    const auto kept = views.out.substr(views.out.find("{\"brdf_kept_curves\":2"));
    const auto labels = nlohmann::json::parse(kept.substr(0, kept.find('\n')))["labels"];
    // Curves of one file tell apart: numbered, the second names the parameter that changed.
    CHECK(labels[0].get<std::string>().rfind("#1 lambert.brdf", 0) == 0);
    CHECK(labels[1].get<std::string>().find("#2 ") == 0);
    CHECK(labels[1].get<std::string>().find("-> 0.3,0.3,0.3") != std::string::npos);
    // A measured table overlaid on the polar plot (a synthetic Lambertian MERL file); a missing file is named.
    const std::string merl = temp_path("tab-lambert.binary");
    REQUIRE(run("brdf-grid --model phong --param ks=0 --param kd=0.5,0.5,0.5 --merl-out --out " + merl).exit_code == 0);
    std::ofstream(script) << "brdf-measured " << merl << "\nframes 2\n";
    const Result measured = run("view " + lambert + " --render-size 32x32 --script " + script + " --frames 2");
    CHECK(measured.exit_code == 0);
    CHECK(measured.out.find("\"brdf_measured\"") != std::string::npos);
    std::ofstream(script) << "brdf-measured /no/such/file.binary\n";
    const Result missing = run("view " + lambert + " --render-size 32x32 --script " + script + " --frames 2");
    CHECK(missing.exit_code != 0);
    CHECK(missing.err.find("/no/such/file.binary") != std::string::npos);
    std::ofstream(script) << "brdf-check\n";
    const Result refused = run("view " + std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/debug.fx --render-size 32x32 --script " + script + " --frames 2");
    CHECK(refused.exit_code != 0);
    CHECK(refused.err.find("no BRDF grid") != std::string::npos);
}

TEST_CASE("the viewer lights and shows the environment as render does, through the same display transform; a bad one keeps the last good") {
    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx";
    const std::string preset = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/presets/gold.json";
    const std::string shot = temp_path("env-view.png"), rendered = temp_path("env-render.png"), after = temp_path("env-after.png");
    const std::string script = temp_path("env-script.txt");
    // The preset asks for the studio, PBR Neutral and 4x MSAA; a missing file is named and changes nothing.
    std::ofstream(script) << "render-screenshot " << shot << "\nenvironment /no/such/place.hdr\nrender-screenshot " << after << "\n";
    const Result r = run("view " + effect + " --preset " + preset + " --size 64x64 --script " + script + " --frames 2");
    CAPTURE(r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("/no/such/place.hdr") != std::string::npos);
    REQUIRE(run("render " + effect + " --preset " + preset + " --size 64x64 --out " + rendered).exit_code == 0);
    const auto view = load_png(shot), render = load_png(rendered), kept = load_png(after);
    // Same scene, environment, MSAA and display transform: the same 8-bit pixels up to one code value
    // (the two multisample resolves may round differently at edges), object and background alike.
    for (const auto& [x, y] : {std::pair{32, 32}, std::pair{20, 24}, std::pair{44, 40}, std::pair{2, 2}, std::pair{60, 5}})
        for (int c = 0; c < 3; ++c) {
            CHECK(std::abs(texel(view, x, y)[c] - texel(render, x, y)[c]) <= 1.0f / 255.0f + 1e-6f);
            CHECK(texel(kept, x, y)[c] == texel(view, x, y)[c]);
        }
    CHECK(texel(view, 32, 32)[0] > texel(view, 32, 32)[2] + 0.1f);  // gold, not grey
    CHECK(texel(view, 2, 2)[1] > 0.2f);                               // the studio behind it, not black
    // Exposure by script brightens the picture by the transform's rule.
    std::ofstream(script) << "exposure 1\nrender-screenshot " << after << "\n";
    REQUIRE(run("view " + effect + " --preset " + preset + " --size 64x64 --script " + script + " --frames 2").exit_code == 0);
    CHECK(texel(load_png(after), 2, 2)[1] > texel(view, 2, 2)[1] + 0.05f);
}

// The viewer's screenshot against render's picture at three pixels (within an 8-bit code), and
// whether `other` differs from it there: a scene setting set by script as the Scene tab sets it.
bool matches_render_and_differs_from(const fxview::texture::TextureData& view, const fxview::texture::TextureData& render,
                                     const fxview::texture::TextureData& other) {
    bool differs = false;
    for (const auto& [x, y] : {std::pair{24, 24}, std::pair{16, 20}, std::pair{30, 30}})
        for (int c = 0; c < 3; ++c) {
            CHECK(std::abs(texel(view, x, y)[c] - texel(render, x, y)[c]) <= 1.0f / 255.0f + 1e-6f);
            differs = differs || std::abs(texel(other, x, y)[c] - texel(view, x, y)[c]) > 2.0f / 255.0f;
        }
    return differs;
}

TEST_CASE("the light's spectrum set by script (as the Scene tab) gives render --light-spectrum's picture; an unknown name is refused") {
    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/wavelength.fx";
    const std::string shot = temp_path("light-view.png"), rendered = temp_path("light-render.png"), own = temp_path("light-own.png");
    const std::string script = temp_path("light-script.txt");
    std::ofstream(script) << "light-spectrum F11\nrender-screenshot " << shot << "\nlight-spectrum Candle\nlight-spectrum none\nrender-screenshot " << own << "\n";
    const Result r = run("view " + effect + " -t Phong --size 48x48 --script " + script + " --frames 2");
    CAPTURE(r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("light spectrum 'Candle' is not in the spectral library") != std::string::npos);
    REQUIRE(run("render " + effect + " -t Phong --light-spectrum F11 --size 48x48 --out " + rendered).exit_code == 0);
    const auto view = load_png(shot), render = load_png(rendered), back = load_png(own);
    const bool differs = matches_render_and_differs_from(view, render, back);
    CHECK(differs);  // "none" gives the effect its own D65 back
}

TEST_CASE("the light's shape set by script (as the Scene tab) gives render --light-shape's picture; a bad size is refused") {
    const std::string effect = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/spectral/wavelength.fx";
    const std::string shot = temp_path("shape-view.png"), rendered = temp_path("shape-render.png"), point = temp_path("shape-point.png");
    const std::string script = temp_path("shape-script.txt");
    std::ofstream(script) << "light-shape rectangle 3 1\nrender-screenshot " << shot << "\nlight-shape disc -1\nlight-shape sphere 0\nrender-screenshot " << point << "\n";
    const Result r = run("view " + effect + " -t Phong --size 48x48 --script " + script + " --frames 2");
    CAPTURE(r.err);
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("light-shape: sizes from 0 to 1000") != std::string::npos);
    REQUIRE(run("render " + effect + " -t Phong --light-shape rectangle --light-size 3,1 --size 48x48 --out " + rendered).exit_code == 0);
    const auto view = load_png(shot), render = load_png(rendered), back = load_png(point);
    const bool differs = matches_render_and_differs_from(view, render, back);
    CHECK(differs);  // a point light again: another picture
}

TEST_CASE("a large UI scale keeps the tabs' names whole; a shrunk window gets a share of the panel, its width comes back") {
    const std::string script = temp_path("panel-script.txt");
    std::ofstream(script) << "ui-state\nwindow 640 480\nui-state\nwindow 1280 800\nui-state\n";
    const Result r = run("view " + kDebugFx + " --ui-scale 1.6 --window 1280x800 --script " + script + " --frames 1");
    REQUIRE(r.exit_code == 0);
    const auto states = json_lines(r.out);
    REQUIRE(states.size() == 3);
    const auto& wide = states[0], &narrow = states[1], &again = states[2];
    CHECK(wide["window"] == nlohmann::json::array({1280, 800}));
    // At 1.6 the seven tabs need more than the 45 % a panel usually takes (576 px): it is widened for them.
    CHECK(wide["tab_bar_width"].get<double>() > 0.45 * 1280 - 40);
    CHECK(wide["tabs_fit"] == true);
    CHECK(wide["panel_width"].get<double>() <= 0.55 * 1280 + 0.5);
    // 640 wide: the panel takes 55 % of the window (not its 1280-wide width, which would be 95 % of it).
    CHECK(narrow["window"] == nlohmann::json::array({640, 480}));
    CHECK(narrow["panel_width"].get<double>() == doctest::Approx(0.55 * 640).epsilon(0.01));
    CHECK(again["panel_width"].get<double>() == doctest::Approx(wide["panel_width"].get<double>()));
}

#ifdef FXVIEW_HAVE_XTEST
TEST_CASE("a key tap shorter than a frame reaches the viewer: H shows the key help") {
    const std::string script = temp_path("tap-script.txt");
    std::ofstream(script) << "ui-state\nwait-key H 60\nframes 2\nui-state\n";
    // The viewer's output read as it comes: the tap is sent once the first state is printed, when the
    // script is already waiting for the key (wait-key runs in the same frame).
    const std::string command = std::string(FXVIEW_BINARY) + " view " + kDebugFx + " --window 640x480 --script " + script + " --frames 1";
    FILE* viewer = popen(command.c_str(), "r");
    REQUIRE(viewer != nullptr);
    std::string out;
    bool tapped = false;
    std::array<char, 4096> line{};
    while (std::fgets(line.data(), line.size(), viewer)) {
        out += line.data();
        // Press and release sent together: both arrive between two frames, as a quick tap does.
        if (!tapped && std::string(line.data()).find("\"help\"") != std::string::npos)
            tapped = fxview::test::tap_key_in_window("fxview", "h", 60);
    }
    const int status = pclose(viewer);
    REQUIRE(tapped);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    const auto states = json_lines(out);
    REQUIRE(states.size() == 2);
    CHECK(states[0]["help"] == false);
    CHECK(states[1]["help"] == true);
}
#endif

TEST_CASE("the Effect tab lists the loader's warnings, as the command line prints them") {
    // A .brdf file with an importance-sampling section and an unknown one: two warnings at their lines.
    const std::string file = std::string(FXVIEW_TEST_EFFECTS) + "/brdf/explorer/is_func.brdf", script = temp_path("warnings.txt");
    std::ofstream(script) << "ui-state\n";
    const Result r = run("view " + file + " --window 640x480 --script " + script + " --frames 1");
    REQUIRE(r.exit_code == 0);
    const auto states = json_lines(r.out);
    REQUIRE(states.size() == 1);
    CHECK(states[0]["warnings"] == 2);
}
