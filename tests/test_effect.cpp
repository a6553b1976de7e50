// Effect files: the parser on a valid file using every feature, the malformed corpus (each file
// states the `file:line: message` it must produce), SAS matrices against GLM, parameter values,
// and GPU rendering through effects (debug.fx against the built-in renderer, multi-pass blending).
#include <doctest/doctest.h>

#include "test_support.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>

#include "context/context.hpp"
#include "effect/effect_program.hpp"
#include "effect/parameter_values.hpp"
#include "effect/parser.hpp"
#include "gl/render_target.hpp"
#include "render/debug_renderer.hpp"
#include "effect/preset.hpp"
#include "render/effect_renderer.hpp"
#include "render/effect_session.hpp"
#include "texture/texture_file.hpp"

using namespace fxview;
using fxview::test::shared_context;
using fxview::test::temp_path;
namespace fs = std::filesystem;

namespace {

const std::string kEffects = FXVIEW_SOURCE_EFFECTS_DIR;
const std::string kCorpus = FXVIEW_TEST_EFFECTS;

effect::LoadOptions load_options() { return {{kEffects + "/lib"}, {}}; }

// Parses and compiles every technique; returns the first error's text, or "" if all is well.
std::string first_error(const std::string& path) {
    try {
        const effect::Effect effect = effect::load_effect(path, load_options());
        shared_context();
        for (const auto& technique : effect.techniques) effect::compile_technique(effect, technique);
        render::EffectResources resources(effect, effect::default_values(effect), {});
    } catch (const effect::EffectError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST_CASE("a valid effect with every feature parses as written") {
    const effect::Effect e = effect::load_effect(kCorpus + "/valid/everything.fx", load_options());
    REQUIRE(e.techniques.size() == 1);
    const effect::Technique& main = e.techniques[0];
    CHECK(main.name == "Main");
    REQUIRE(main.passes.size() == 2);
    CHECK(main.passes[0].name == "base");
    CHECK(main.passes[1].name == "p1");  // unnamed pass
    CHECK(main.passes[0].shaders.at(effect::ShaderStage::Vertex) == "StandardVS");  // CgFX "compile" syntax
    CHECK(main.passes[1].shaders.at(effect::ShaderStage::Fragment) == "ColorFS");    // PixelShader alias
    const effect::RenderStates& s = main.passes[0].states;
    CHECK(s.depth_write == false);
    CHECK(s.depth_func == GL_LEQUAL);
    CHECK(s.cull == true);
    CHECK(s.cull_face == GL_BACK);
    CHECK(s.blend == true);
    CHECK(s.blend_src == GL_SRC_ALPHA);
    CHECK(s.blend_dst == GL_ONE_MINUS_SRC_ALPHA);
    CHECK(s.color_mask == std::array<bool, 4>{true, true, false, true});
    CHECK(s.clear_color->at(2) == doctest::Approx(0.3f));
    // States reset at each pass: the second pass sets only depth test and keeps every other default.
    const effect::RenderStates& second = main.passes[1].states;
    CHECK(second.depth_test == false);
    CHECK(second.blend == false);
    CHECK(second.depth_write == true);

    const effect::Parameter* roughness = e.find_parameter("Roughness");
    REQUIRE(roughness);
    CHECK(roughness->ui.label == "Roughness");
    CHECK(roughness->ui.widget == "slider");
    CHECK(*roughness->ui.min == 0.0);
    CHECK(*roughness->ui.max == 1.0);
    CHECK(*roughness->ui.step == 0.01);
    CHECK(roughness->ui.group == "Surface");
    CHECK(roughness->ui.order == 2);
    CHECK(roughness->ui.help == "Microfacet roughness");
    const effect::Parameter* tint = e.find_parameter("Tint");  // DXSAS spelling
    CHECK(tint->ui.label == "Tint");
    CHECK(tint->ui.widget == "colorpicker");
    CHECK(*tint->ui.max == 1.0);
    CHECK(tint->default_value->numbers == std::vector<double>{0.25, 0.25, 0.25});  // vec3(0.25) broadcast
    const effect::Parameter* mode = e.find_parameter("Mode");  // Maya spelling
    CHECK(mode->ui.items == std::vector<std::string>{"off", "on", "auto"});
    CHECK(e.find_parameter("Offsets")->array_size == 2);
    CHECK(e.find_parameter("Offsets")->default_value->numbers.size() == 8);
    CHECK(e.find_parameter("Wvp")->semantic == "WORLDVIEWPROJECTION");  // case-insensitive
    CHECK(e.find_parameter("Enabled")->default_value->numbers == std::vector<double>{1.0});
    // #pragma once: standard.glsl's parameters appear once although it is included twice.
    CHECK(std::count_if(e.parameters.begin(), e.parameters.end(), [](const auto& p) { return p.name == "World"; }) == 1);
    CHECK(first_error(kCorpus + "/valid/everything.fx") == "");
}

TEST_CASE("every file of the malformed corpus gives its own message at its own file:line") {
    int files = 0;
    for (const auto& entry : fs::directory_iterator(kCorpus + "/malformed")) {
        if (entry.path().extension() != ".fx") continue;
        ++files;
        std::ifstream file(entry.path());
        std::string header;
        std::getline(file, header);
        std::smatch expect;
        const std::string name = entry.path().filename().string();
        CAPTURE(name);
        REQUIRE(std::regex_match(header, expect, std::regex(R"(// expect: (?:(\S+\.\w+):)?(\d+): (.*))")));
        const std::string expected_file = expect[1].matched ? expect[1].str() : name;
        const std::string error = first_error(entry.path().string());
        CAPTURE(error);
        REQUIRE(!error.empty());
        std::smatch got;
        REQUIRE(std::regex_search(error, got, std::regex(R"(^(\S+?):(\d+): )")));
        CHECK(fs::path(got[1].str()).filename().string() == expected_file);
        CHECK(got[2].str() == expect[2].str());
        CHECK(error.find(expect[3].str()) != std::string::npos);
    }
    CHECK(files >= 25);
}

TEST_CASE("SAS matrices equal the GLM products") {
    effect::FrameContext f;
    f.world = glm::translate(glm::mat4(1), {1, 2, 3}) * glm::rotate(glm::mat4(1), 0.3f, glm::vec3(0, 1, 0));
    f.view = glm::lookAt(glm::vec3(0, 1, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    f.projection = glm::perspective(0.8f, 1.5f, 0.1f, 50.0f);
    const auto equal = [](const std::vector<float>& value, const glm::mat4& m) {
        return value.size() == 16 && std::memcmp(value.data(), glm::value_ptr(m), 64) == 0;
    };
    CHECK(equal(effect::semantic_value("WORLD", f, 16), f.world));
    CHECK(equal(effect::semantic_value("VIEW", f, 16), f.view));
    CHECK(equal(effect::semantic_value("PROJECTION", f, 16), f.projection));
    CHECK(equal(effect::semantic_value("WORLDVIEW", f, 16), f.view * f.world));
    CHECK(equal(effect::semantic_value("VIEWPROJECTION", f, 16), f.projection * f.view));
    CHECK(equal(effect::semantic_value("WORLDVIEWPROJECTION", f, 16), f.projection * f.view * f.world));
    CHECK(equal(effect::semantic_value("WORLDINVERSE", f, 16), glm::inverse(f.world)));
    CHECK(equal(effect::semantic_value("VIEWTRANSPOSE", f, 16), glm::transpose(f.view)));
    CHECK(equal(effect::semantic_value("WORLDVIEWINVERSETRANSPOSE", f, 16), glm::transpose(glm::inverse(f.view * f.world))));
    const auto normal = effect::semantic_value("WORLDINVERSETRANSPOSE", f, 9);
    const glm::mat3 expected(glm::transpose(glm::inverse(f.world)));
    CHECK(std::memcmp(normal.data(), glm::value_ptr(expected), 36) == 0);
    f.light_position = {0, 0, 2};
    CHECK(effect::semantic_value("LIGHTDIRECTION", f, 3)[2] == -1.0f);
    CHECK(effect::is_known_semantic("PROJECTIONINVERSE"));
    CHECK(!effect::is_known_semantic("WORLDVIEWPROJ"));
}

TEST_CASE("--set values: numbers, vectors, hex colours, booleans; bad ones named") {
    const effect::Effect e = effect::load_effect(kCorpus + "/valid/everything.fx", load_options());
    effect::ParameterValues values = effect::default_values(e);
    CHECK(values.numbers.at("Roughness") == std::vector<double>{0.5});
    CHECK(!values.numbers.count("Wvp"));  // semantics are not user values
    effect::set_value_from_text(e, values, "Roughness=0.75");
    CHECK(values.numbers.at("Roughness") == std::vector<double>{0.75});
    effect::set_value_from_text(e, values, "Tint=#ff8000");
    // sRGB 0x80 = 128/255 decodes to linear 0.21586 (IEC 61966-2-1).
    CHECK(values.numbers.at("Tint")[0] == doctest::Approx(1.0));
    CHECK(values.numbers.at("Tint")[1] == doctest::Approx(0.215861).epsilon(1e-5));
    CHECK(values.numbers.at("Tint")[2] == 0.0);
    effect::set_value_from_text(e, values, "Enabled=false");
    CHECK(values.numbers.at("Enabled") == std::vector<double>{0.0});
    effect::set_value_from_text(e, values, "Tint=1,0,0.5");
    CHECK(values.numbers.at("Tint") == std::vector<double>{1, 0, 0.5});
    CHECK_THROWS_WITH_AS(effect::set_value_from_text(e, values, "Tint=1,0"), doctest::Contains("vec3 needs 3"), UsageError);
    CHECK_THROWS_WITH_AS(effect::set_value_from_text(e, values, "Nope=1"), doctest::Contains("no parameter 'Nope'"), UsageError);
    CHECK_THROWS_WITH_AS(effect::set_value_from_text(e, values, "Wvp=1"), doctest::Contains("semantic"), UsageError);
    CHECK_THROWS_AS(effect::set_value_from_text(e, values, "Roughness=abc"), UsageError);
    CHECK_THROWS_AS(effect::set_value_from_text(e, values, "Roughness"), UsageError);
}

TEST_CASE("debug.fx Normals renders exactly the built-in normal view") {
    shared_context();
    const effect::Effect e = effect::load_effect(kEffects + "/debug.fx", load_options());
    for (const char* name : {"Normals", "TexCoords", "VectorToCamera", "VectorToLight", "Plain"}) CHECK(e.find_technique(name));
    scene::Scene scene;
    scene.objects.front().mesh = "torus";
    scene.objects.front().pose.rotation = glm::angleAxis(0.5f, glm::normalize(glm::vec3(1, 1, 0)));
    const std::pair<const char*, render::DebugView> pairs[] = {{"Normals", render::DebugView::Normals},
                                                               {"TexCoords", render::DebugView::TexCoords},
                                                               {"VectorToCamera", render::DebugView::ToCamera},
                                                               {"VectorToLight", render::DebugView::ToLight}};
    for (const auto& pair : pairs) {
        const char* technique = pair.first;  // not a structured binding: clang 14 cannot capture those
        const render::DebugView view = pair.second;
        CAPTURE(technique);
        gl::RenderTarget a({96, 64, 1, 0}), b({96, 64, 1, 0});
        render::DebugRenderer debug;
        debug.render(scene, view, a);
        const auto compiled = effect::compile_technique(e, *e.find_technique(technique));
        render::EffectRenderer renderer;
        render::EffectResources resources(e, effect::default_values(e), {});
        renderer.render(scene, compiled, effect::default_values(e), resources, b);
        const auto expected = a.read_color(), actual = b.read_color();
        // Same vertex maths and the same fragment formula: the pictures agree to 1e-6 (the effect
        // computes the normal matrix from the SAS semantic, the built-in from the same GLM call).
        float worst = 0.0f;
        for (size_t i = 0; i < expected.data.size(); ++i) worst = std::max(worst, std::abs(expected.data[i] - actual.data[i]));
        CHECK(worst <= 1e-6f);
    }
}

TEST_CASE("two passes with additive blending add exactly") {
    shared_context();
    const effect::Effect e = effect::load_effect(kCorpus + "/valid/additive.fx", load_options());
    const auto compiled = effect::compile_technique(e, e.techniques.front());
    gl::RenderTarget target({64, 64, 1, 0});
    render::EffectRenderer renderer;
    render::EffectResources resources(e, effect::default_values(e), {});
    renderer.render(scene::Scene{}, compiled, effect::default_values(e), resources, target);
    const auto image = target.read_color();
    CHECK(image.pixel(32, 32)[0] == 0.5f);  // 0.25 + 0.25
    CHECK(image.pixel(32, 32)[3] == 1.0f);  // alpha masked in the second pass: not 2
    CHECK(image.pixel(0, 0)[0] == 0.0f);    // background untouched
}

TEST_CASE("multi-pass through render targets (MRT, full-screen pass) equals twice the normal view") {
    shared_context();
    const effect::Effect e = effect::load_effect(kCorpus + "/valid/multipass.fx", load_options());
    const auto compiled = effect::compile_technique(e, e.techniques.front());
    render::EffectResources resources(e, effect::default_values(e), {});
    scene::Scene scene;
    gl::RenderTarget target({80, 64, 1, 0}), reference({80, 64, 1, 0});
    render::EffectRenderer renderer;
    renderer.render(scene, compiled, effect::default_values(e), resources, target);
    render::DebugRenderer debug;
    debug.render(scene, render::DebugView::Normals, reference);
    const auto actual = target.read_color(), expected = reference.read_color();
    int mismatches = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 80; ++x)
            for (int c = 0; c < 4; ++c) {
                const float want = c < 3 ? 2.0f * expected.pixel(x, y)[c] : expected.pixel(x, y)[c];
                // 1e-6: the G-buffer pass and the built-in view evaluate the same expression.
                if (std::abs(actual.pixel(x, y)[c] - want) > 1e-6f) ++mismatches;
            }
    CHECK(mismatches == 0);
    // The render targets follow the frame size.
    CHECK(resources.find("Normals")->width == 80);
    CHECK(resources.find("Coords")->height == 64);
}

TEST_CASE("a texture file sampled with nearest filtering comes back texel for texel") {
    shared_context();
    const effect::Effect e = effect::load_effect(kCorpus + "/valid/textured.fx", load_options());
    const auto compiled = effect::compile_technique(e, e.techniques.front());
    render::EffectResources resources(e, effect::default_values(e), {});
    CHECK(resources.find("Image")->format == texture::PixelFormat::RGBA32F);
    CHECK(resources.find("Quantised")->format == texture::PixelFormat::RGBA8);  // Format = "8"
    gl::RenderTarget target({4, 2, 2, 0});
    render::EffectRenderer renderer;
    renderer.render(scene::Scene{}, compiled, effect::default_values(e), resources, target);
    const auto image = target.read_color(0), quantised = target.read_color(1);
    const texture::TextureData file = texture::load_texture_file(kCorpus + "/valid/pattern.ftxt");
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
            float expected[4];
            texture::read_texel(file, 0, 0, x, y, expected);
            for (int c = 0; c < 4; ++c) {
                CHECK(image.pixel(x, y)[c] == expected[c]);  // float texture: exact
                // 8-bit storage: the value rounded to the nearest of 256 codes (clamped to [0,1]).
                const float code = std::round(std::clamp(expected[c], 0.0f, 1.0f) * 255.0f) / 255.0f;
                CHECK(std::abs(quantised.pixel(x, y)[c] - code) <= 1e-6f);
            }
        }
}

namespace {

void write_text(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
    // File times can be coarse: move the modification time on explicitly so the change is seen.
    fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(2));
}

std::string constant_effect(const std::string& declarations, const std::string& body) {
    return "#include \"fullscreen.glsl\"\n" + declarations +
           "\nGLSLShader FS { layout(location = 0) out vec4 c; void main() { " + body + " } }\n"
           "technique T { pass p { VertexShader = FullscreenVS; FragmentShader = FS; Draw = Buffer; } }\n";
}

}  // namespace

TEST_CASE("hot reload keeps the last good effect and the edited values") {
    shared_context();
    const std::string path = temp_path("reload.fx");
    write_text(path, constant_effect("uniform float Gain = 0.25;\nuniform vec3 Tint = {1, 1, 1};", "c = vec4(Tint * Gain, 1.0);"));
    render::EffectSession session(path, load_options(), {});
    session.values().numbers["Gain"] = {0.5};  // the user's edit
    gl::RenderTarget target({4, 4, 1, 0});
    const auto red_at_centre = [&] {
        session.render(scene::Scene{}, target);
        return target.read_color().pixel(2, 2)[0];
    };
    CHECK(red_at_centre() == 0.5f);
    CHECK(!session.files_changed());

    // A GLSL error: the reload fails with file:line, the old effect keeps rendering with the edit.
    write_text(path, constant_effect("uniform float Gain = 0.25;\nuniform vec3 Tint = {1, 1, 1};", "c = vec4(Tint * Gain, 1.0) +;"));
    CHECK(session.files_changed());
    const auto error = session.reload_if_changed();
    REQUIRE(error.has_value());
    CHECK(error->find("reload.fx:4: error") != std::string::npos);
    CHECK(red_at_centre() == 0.5f);
    CHECK(!session.files_changed());  // the broken version is not retried every frame

    // Fixed, with Tint changed from vec3 to float: Gain keeps the edit, Tint takes its new default.
    write_text(path, constant_effect("uniform float Gain = 0.25;\nuniform float Tint = 2.0;", "c = vec4(vec3(Tint * Gain), 1.0);"));
    CHECK(!session.reload_if_changed().has_value());
    CHECK(session.values().numbers.at("Gain") == std::vector<double>{0.5});
    CHECK(session.values().numbers.at("Tint") == std::vector<double>{2.0});
    CHECK(red_at_centre() == 1.0f);

    // An include that changes triggers the reload too.
    const std::string include = temp_path("reload_part.glsl");
    write_text(include, "float part() { return 0.125; }\n");
    write_text(path, "#include \"reload_part.glsl\"\n" + constant_effect("uniform float Gain = 0.25;", "c = vec4(vec3(part() + 0.0 * Gain), 1.0);"));
    CHECK(!session.reload_if_changed().has_value());
    CHECK(red_at_centre() == 0.125f);
    write_text(include, "float part() { return 0.75; }\n");
    CHECK(session.files_changed());
    CHECK(!session.reload_if_changed().has_value());
    CHECK(red_at_centre() == 0.75f);
}

TEST_CASE("presets save and restore every value; bad presets are refused whole") {
    const effect::Effect e = effect::load_effect(kCorpus + "/valid/everything.fx", load_options());
    effect::ParameterValues values = effect::default_values(e);
    values.numbers["Roughness"] = {0.125};
    values.numbers["Tint"] = {0.1, 0.2, 0.3};
    const std::string path = temp_path("preset.json");
    effect::save_preset(path, e, "Main", values);
    effect::ParameterValues restored = effect::default_values(e);
    const effect::Preset preset = effect::load_preset(path, e, restored);
    CHECK(preset.technique == "Main");
    CHECK(restored.numbers == values.numbers);

    const std::string bad = temp_path("bad_preset.json");
    std::ofstream(bad) << R"({"parameters": {"Roughness": 0.9, "Tint": [1, 2]}})";
    effect::ParameterValues untouched = effect::default_values(e);
    CHECK_THROWS_WITH_AS(effect::load_preset(bad, e, untouched), doctest::Contains("gives 2 value(s) for vec3 Tint"), Error);
    CHECK(untouched.numbers.at("Roughness") == std::vector<double>{0.5});  // all or nothing
    std::ofstream(bad) << R"({"parameters": {"Wvp": 1}})";
    CHECK_THROWS_WITH_AS(effect::load_preset(bad, e, untouched), doctest::Contains("no editable parameter"), Error);
    std::ofstream(bad) << "{ not json";
    CHECK_THROWS_WITH_AS(effect::load_preset(bad, e, untouched), doctest::Contains("bad_preset.json:1: not a valid JSON preset"), Error);
}

TEST_CASE("a sampler3D reads the slices of a stacked image") {
    shared_context();
    const effect::Effect e = effect::load_effect(kCorpus + "/valid/volume.fx", load_options());
    const auto compiled = effect::compile_technique(e, e.techniques.front());
    render::EffectResources resources(e, effect::default_values(e), {});
    gl::RenderTarget target({1, 2, 1, 0});
    render::EffectRenderer renderer;
    renderer.render(scene::Scene{}, compiled, effect::default_values(e), resources, target);
    const auto image = target.read_color();
    CHECK(image.pixel(0, 0)[0] == 3.0f);  // slice 1, top row
    CHECK(image.pixel(0, 1)[0] == 4.0f);  // slice 1, bottom row
}

TEST_CASE("an effect opens on its technique annotated Default, else on its first") {
    CHECK(effect::load_effect(kEffects + "/debug.fx", load_options()).default_technique().name ==
          effect::load_effect(kEffects + "/debug.fx", load_options()).techniques.front().name);
    // The shipped effects open on their most representative technique, not on the thesis' simplest.
    const std::pair<const char*, const char*> shipped[] = {{"/spectral/wavelength.fx", "Phong"}, {"/spectral/thinfilm.fx", "FresnelExact"},
                                                           {"/spectral/cd.fx", "Orders"}, {"/brdf/analytic.fx", "PBR"}};
    for (const auto& [file, technique] : shipped) {
        CAPTURE(file);
        CHECK(effect::load_effect(kEffects + file, load_options()).default_technique().name == technique);
    }
}

TEST_CASE("a technique's parameters are those its programs read: analytic.fx on PBR reads PBR's, not Phong's") {
    shared_context();
    render::EffectSession session(std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/brdf/analytic.fx", load_options(), {});
    const std::set<std::string> pbr = session.parameters_read("PBR");
    for (const char* used : {"LightIrradiance", "BaseColor", "Metallic", "Roughness"}) CHECK(pbr.count(used) == 1);
    for (const char* unused : {"PhongDiffuse", "Nu", "FitExponent", "GGXAlpha", "WardAlpha"}) CHECK(pbr.count(unused) == 0);
    const std::set<std::string> ggx = session.parameters_read("CookTorranceGGX");
    CHECK(ggx.count("GGXAlpha") == 1);
    CHECK(ggx.count("Roughness") == 0);
    CHECK(session.parameters_read("NoSuchTechnique").empty());
    CHECK(!session.animated("PBR"));
    CHECK(!session.renders_to_textures("PBR"));
}

TEST_CASE("techniques that read TIME are animated; passes into render targets are reported") {
    shared_context();
    const std::string timed = temp_path("timed.fx");
    write_text(timed, constant_effect("uniform float Seconds : TIME;", "c = vec4(fract(Seconds), 0.0, 0.0, 1.0);"));
    render::EffectSession session(timed, load_options(), {});
    CHECK(session.animated(session.technique()));
    render::EffectSession multipass(std::string(FXVIEW_TEST_EFFECTS) + "/valid/multipass.fx", load_options(), {});
    bool any = false;
    for (const auto& t : multipass.effect().techniques) any = any || multipass.renders_to_textures(t.name);
    CHECK(any);
}

TEST_CASE("an effect whose techniques fail to compile reports every technique's errors, each at its file:line") {
    shared_context();
    const std::string path = temp_path("two-bad.fx");
    write_text(path, "#include \"fullscreen.glsl\"\n"
                     "GLSLShader BadA { layout(location = 0) out vec4 c; void main() { c = vec4(nope_a); } }\n"
                     "GLSLShader BadB { layout(location = 0) out vec4 c; void main() { c = vec4(nope_b); } }\n"
                     "technique A { pass p { VertexShader = FullscreenVS; FragmentShader = BadA; Draw = Buffer; } }\n"
                     "technique B { pass p { VertexShader = FullscreenVS; FragmentShader = BadB; Draw = Buffer; } }\n");
    try {
        render::EffectSession session(path, load_options(), {});
        FAIL("the broken effect loaded");
    } catch (const effect::EffectError& error) {
        const std::string message = error.what();
        CHECK(message.find("two-bad.fx:2:") != std::string::npos);  // technique A's shader
        CHECK(message.find("two-bad.fx:3:") != std::string::npos);  // and technique B's
    }
}
