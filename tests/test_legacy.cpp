// Legacy effects (Cg/HLSL, docs/legacy-effects.md) from the project's own corpus in
// tests/effects/legacy: what the effect level reads, that translated techniques draw the object
// where fxview's own debug view draws it and lit from the light, that the matrix convention
// matters, post-processing through render targets, placeholders, errors at file:line, hot reload.
#include <doctest/doctest.h>

#include "test_support.hpp"

#include <cmath>
#include <cstring>
#include <fstream>

#include "core/text.hpp"
#include "effect/effect_program.hpp"
#include "effect/parser.hpp"
#include "gl/render_target.hpp"
#include "render/debug_renderer.hpp"
#include "render/effect_session.hpp"

using namespace fxview;
using fxview::test::shared_context;
using fxview::test::temp_path;

namespace {

const std::string kLegacy = std::string(FXVIEW_TEST_EFFECTS) + "/legacy";

effect::LoadOptions load_options(const std::string& convention = "") {
    effect::LoadOptions options;
    options.include_dirs = {std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/lib"};
    options.matrix_convention = convention;
    options.access.allow_folder(std::filesystem::path(FXVIEW_SOURCE_EFFECTS_DIR).parent_path() / "textures");  // as the CLI allows
    return options;
}

image::FloatImage render_effect(const std::string& file, const std::string& convention = "", int size = 64) {
    shared_context();
    render::EffectSession session(kLegacy + "/" + file, load_options(convention), {});
    gl::RenderTarget target({size, size, 1, 0});
    session.render(scene::Scene{}, target);
    REQUIRE(glGetError() == GL_NO_ERROR);
    return target.read_color(0);
}

image::FloatImage debug_view(int size = 64) {
    shared_context();
    gl::RenderTarget target({size, size, 1, 0});
    render::DebugRenderer renderer;
    renderer.render(scene::Scene{}, render::DebugView::Normals, target);
    return target.read_color(0);
}

// Intersection over union of the covered pixels (alpha > 0) of two pictures.
double overlap(const image::FloatImage& a, const image::FloatImage& b) {
    int both = 0, either = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const bool in_a = a.pixel(x, y)[3] > 0, in_b = b.pixel(x, y)[3] > 0;
            both += in_a && in_b;
            either += in_a || in_b;
        }
    return either ? static_cast<double>(both) / either : 0.0;
}

double luminance(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

const effect::Parameter& parameter(const effect::Effect& e, const std::string& name) {
    const effect::Parameter* p = e.find_parameter(name);
    REQUIRE_MESSAGE(p != nullptr, name);
    return *p;
}

}  // namespace

TEST_CASE("a DX9 effect's parameters keep their names, annotations, semantics and sampler states") {
    const effect::Effect e = effect::load_effect(kLegacy + "/plastic_dx9.fx", load_options());
    CHECK(e.legacy);
    CHECK(e.row_vectors);  // mul(v, M) throughout
    CHECK(parameter(e, "WvpXf").type == "mat4");
    CHECK(parameter(e, "WvpXf").semantic == "WORLDVIEWPROJECTION");
    CHECK(parameter(e, "WorldITXf").semantic == "WORLDINVERSETRANSPOSE");
    CHECK(parameter(e, "ViewIXf").semantic == "VIEWINVERSE");
    CHECK(parameter(e, "Lamp0Pos").semantic == "LIGHTPOSITION");  // Position with Object = "PointLight0"
    const effect::Parameter& power = parameter(e, "SpecExpon");
    CHECK(power.ui.label == "Specular Power");
    CHECK(power.ui.min == 1.0);
    CHECK(power.ui.max == 128.0);
    CHECK(power.default_value->numbers == std::vector<double>{30.0});
    CHECK(parameter(e, "SurfaceColor").semantic.empty());  // DIFFUSE is a material value the user edits
    CHECK(parameter(e, "SurfaceColor").ui.widget == "color");
    const effect::Parameter& sampler = parameter(e, "ColorSampler");
    CHECK(sampler.texture == "ColorTexture");
    CHECK(sampler.sampler.wrap_s == GL_REPEAT);
    CHECK(sampler.sampler.wrap_t == GL_CLAMP_TO_EDGE);
    CHECK(sampler.sampler.min_filter == GL_LINEAR_MIPMAP_LINEAR);  // MinFilter = Linear + MipFilter = Linear
    CHECK(e.find_parameter("Script") == nullptr);  // the STANDARDSGLOBAL is the effect's, not a parameter
    REQUIRE(e.techniques.size() == 1);
    CHECK(e.techniques[0].passes[0].states.depth_func == GL_LEQUAL);
    CHECK(!e.techniques[0].passes[0].states.cull);  // CullMode = None
}

TEST_CASE("a CgFX effect: column vectors, Cg types, an include through a Windows path, CgFX states") {
    const effect::Effect e = effect::load_effect(kLegacy + "/plastic_cg.cgfx", load_options());
    CHECK(!e.row_vectors);  // mul(M, v)
    CHECK(parameter(e, "DiffuseColor").type == "vec3");  // half3
    CHECK(parameter(e, "ModelViewProj").semantic == "WORLDVIEWPROJECTION");
    CHECK(parameter(e, "Checker").sampler.min_filter == GL_LINEAR_MIPMAP_LINEAR);
    bool include_read = false;
    for (const auto& file : e.sources.files()) include_read = include_read || file.find("common.cgh") != std::string::npos;
    CHECK(include_read);
    bool warned = false;  // ShadeModel is fixed-function: warned about, not fatal
    for (const auto& w : e.warnings) warned = warned || w.find("ShadeModel") != std::string::npos;
    CHECK(warned);
}

TEST_CASE("translated techniques draw the object where the debug view does, lit from the light") {
    const image::FloatImage reference = debug_view();
    for (const std::string file : {"plastic_dx9.fx", "plastic_cg.cgfx"}) {
        CAPTURE(file);
        const image::FloatImage picture = render_effect(file);
        // The silhouettes of one sphere tessellation under one camera: equal up to rasterisation
        // rules at the rim (a ring of ~200 pixels of 64x64 would be 20 %, 2 % allows a few).
        CHECK(overlap(picture, reference) > 0.98);
        double lit = 0, dark = 0, lowest = 1e9, highest = -1e9;
        bool finite = true;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const float* p = picture.pixel(x, y);
                finite = finite && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
                if (reference.pixel(x, y)[3] == 0) continue;
                lowest = std::min(lowest, luminance(p));
                highest = std::max(highest, luminance(p));
            }
        CHECK(finite);
        CHECK(highest - lowest > 0.1);  // shaded, not flat
        // The default light sits up and to the right of the camera: the upper-right of the sphere
        // faces it, the lower-left turns away.
        lit = luminance(picture.pixel(44, 20));
        dark = luminance(picture.pixel(20, 44));
        CHECK(lit > dark + 0.05);
    }
}

TEST_CASE("the matrix convention decides: the opposite one loses the object") {
    const image::FloatImage reference = debug_view();
    // A transposed projection smears the sphere over the frame (measured overlap 0.57 for both
    // files); the right convention reaches > 0.98, so 0.8 separates them with margin.
    CHECK(overlap(render_effect("plastic_dx9.fx", "column"), reference) < 0.8);
    CHECK(overlap(render_effect("plastic_cg.cgfx", "row"), reference) < 0.8);
    CHECK(overlap(render_effect("plastic_cg.cgfx", "column"), reference) > 0.98);
}

TEST_CASE("uniform blocks: row-vector effects store M, column-vector effects M transposed, at the reflected offsets") {
    effect::Parameter matrix;
    matrix.name = "M";
    matrix.type = "mat4";
    effect::Parameter vector;
    vector.name = "V";
    vector.type = "vec3";
    effect::UniformBlockLayout layout;
    layout.size = 96;
    layout.members.push_back({"M", effect::UniformBlockMember::Kind::Float, 0, 4, 4, 0, 0, 16, true});
    layout.members.push_back({"V", effect::UniformBlockMember::Kind::Float, 80, 3, 1, 0, 0, 0, false});
    effect::ParameterValues values;
    std::vector<double> m(16);
    for (int i = 0; i < 16; ++i) m[static_cast<size_t>(i)] = i;  // column-major: M(r, c) = 4c + r
    values.numbers["M"] = m;
    values.numbers["V"] = {7, 8, 9};
    const auto read = [](const std::vector<std::byte>& bytes, size_t offset) {
        float f;
        std::memcpy(&f, bytes.data() + offset, 4);
        return f;
    };
    for (const bool row_vectors : {true, false}) {
        const auto bytes = effect::pack_uniform_block(layout, {&matrix, &vector}, values, {}, row_vectors);
        // Row-major storage of S: S = M for row vectors (S(r, c) = 4c + r), M^T otherwise (4r + c).
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                CHECK(read(bytes, static_cast<size_t>(r * 16 + c * 4)) == static_cast<float>(row_vectors ? 4 * c + r : 4 * r + c));
        CHECK(read(bytes, 80) == 7.0f);
        CHECK(read(bytes, 88) == 9.0f);
    }
}

TEST_CASE("post-processing: a pass script draws into a render target, a screen quad reads it back") {
    const image::FloatImage picture = render_effect("postprocess.fx");
    // Pass Scene: orange object on the ClearColor (0.25, 0.5, 0.75); pass Post inverts. The target
    // is 8-bit (Format A8R8G8B8): 0.5 comes back as 127/255 or 128/255, hence 1/255 of slack.
    const float* centre = picture.pixel(32, 32);
    CHECK(centre[0] == doctest::Approx(0.0).epsilon(0.005));
    CHECK(centre[1] == doctest::Approx(0.5).epsilon(0.005));
    CHECK(centre[2] == doctest::Approx(1.0).epsilon(0.005));
    const float* corner = picture.pixel(1, 1);
    CHECK(corner[0] == doctest::Approx(0.75).epsilon(0.005));
    CHECK(corner[2] == doctest::Approx(0.25).epsilon(0.005));
    const effect::Effect e = effect::load_effect(kLegacy + "/postprocess.fx", load_options());
    REQUIRE(e.techniques.size() == 1);  // technique10 skipped with a note
    CHECK(e.warnings.front().find("technique10 Dx10Only skipped") != std::string::npos);
    // The technique script: ScriptExternal (the scene by the plain shader), then Scene and Post.
    const auto& passes = e.techniques[0].passes;
    REQUIRE(passes.size() == 3);
    CHECK(passes[0].states.draw_scene);
    CHECK(passes[1].name == "Scene");
    CHECK(passes[1].states.render_targets == std::vector<std::string>{"SceneTexture"});
    CHECK(passes[2].states.draw_buffer);
    CHECK(passes[2].states.render_targets.empty());
}

TEST_CASE("a scene glow: technique-script targets, the external scene, a blur through macros of an included header") {
    const image::FloatImage picture = render_effect("glow.fx", "", 128);
    const image::FloatImage reference = debug_view(128);
    // The scene (fxview's plain grey Lambert) reaches the frame through ScnMap; the glow spreads it
    // past the silhouette: a pixel just outside the sphere is no longer the black background.
    CHECK(luminance(picture.pixel(64, 64)) > 0.2);
    int outside = -1;
    for (int x = 127; x > 64; --x)
        if (reference.pixel(x, 64)[3] > 0) { outside = x + 3; break; }
    REQUIRE(outside > 64);
    CHECK(reference.pixel(outside, 64)[3] == 0.0f);
    CHECK(luminance(picture.pixel(outside, 64)) > 0.005);
    CHECK(luminance(picture.pixel(2, 2)) < 1e-4);  // far from the sphere: the clear colour
    const effect::Effect e = effect::load_effect(kLegacy + "/glow.fx", load_options());
    REQUIRE(e.techniques[0].passes.size() == 3);
    CHECK(e.techniques[0].passes[1].states.render_targets == std::vector<std::string>{"BlurMap"});
}

TEST_CASE("LoopByCount=PARAM runs as many passes as the parameter's current value, changed without reloading") {
    shared_context();
    render::EffectSession session(kLegacy + "/loop_count.fx", load_options(), {});
    gl::RenderTarget target({8, 8, 1, 0});
    // Each pass adds 0.1 to the cleared frame (additive blending): the frame holds 0.1 x the passes run.
    for (const int count : {3, 0, 7, 10, 1}) {
        CAPTURE(count);
        session.values().numbers["Count"] = {static_cast<double>(count)};
        session.render(scene::Scene{}, target);
        REQUIRE(glGetError() == GL_NO_ERROR);
        CHECK(target.read_color(0).pixel(4, 4)[0] == doctest::Approx(0.1 * count).epsilon(1e-5));
    }
    // A clear inside the loop body is skipped with its copy: the last iteration's clear and pass remain.
    render::EffectSession inside(kLegacy + "/loop_clear_inside.fx", load_options(), {});
    for (const int count : {1, 3, 10}) {
        CAPTURE(count);
        inside.values().numbers["Count"] = {static_cast<double>(count)};
        inside.render(scene::Scene{}, target);
        CHECK(target.read_color(0).pixel(4, 4)[0] == doctest::Approx(0.1).epsilon(1e-5));
    }
    // Unrolled once to its UIMax (10); the copies share one GL program.
    const effect::Effect e = effect::load_effect(kLegacy + "/loop_count.fx", load_options());
    REQUIRE(e.techniques[0].passes.size() == 10);
    CHECK(e.techniques[0].passes[9].runs_if.size() == 1);
    CHECK(e.techniques[0].passes[9].runs_if[0].iteration == 10);
    const effect::CompiledTechnique compiled = effect::compile_technique(e, e.techniques[0]);
    CHECK(compiled.passes[0].program == compiled.passes[9].program);
}

TEST_CASE("Cg 3 buffer blocks: each member a parameter of its own, semantics supplied by the scene, VAR.member read unchanged") {
    shared_context();
    render::EffectSession session(kLegacy + "/cg3_buffer.cgfx", load_options(), {});
    const effect::Effect& e = session.effect();
    const effect::Parameter* matrix = e.find_parameter("cbuffer0_Transform_modelViewProj");
    REQUIRE(matrix);
    CHECK(to_lower(matrix->semantic) == "worldviewprojection");
    REQUIRE(e.find_parameter("cbuffer1_Material_diffuse"));
    REQUIRE(e.find_parameter("cbuffer1_Material_gain"));
    REQUIRE(e.find_parameter("cbuffer1_Material_unused"));
    CHECK(e.find_parameter("cbuffer1_Material_unused")->array_size == 2);
    bool warned = false;
    for (const auto& w : session.warnings()) warned = warned || w.find("cg3_buffer.cgfx:3: warning: Cg 3 buffer cbuffer0_Transform") != std::string::npos;
    CHECK(warned);
    // The object where the debug view draws it, in the colour the members give.
    session.values().numbers["cbuffer1_Material_diffuse"] = {0.0, 1.0, 0.5, 1.0};
    session.values().numbers["cbuffer1_Material_gain"] = {0.5};
    gl::RenderTarget target({64, 64, 1, 0});
    session.render(scene::Scene{}, target);
    const image::FloatImage picture = target.read_color(0);
    CHECK(overlap(picture, debug_view()) > 0.95);
    CHECK(picture.pixel(32, 32)[1] == doctest::Approx(0.5));
    CHECK(picture.pixel(32, 32)[2] == doctest::Approx(0.25));
    // The error of a compile statement in such a file still names its line (the rewrite keeps lines).
    CHECK(e.techniques.front().passes.front().where.line == 17);
}

TEST_CASE("missing textures become placeholders with a warning naming file and parameter") {
    shared_context();
    render::EffectSession session(kLegacy + "/plastic_dx9.fx", load_options(), {});
    bool named = false;
    for (const auto& w : session.warnings())
        named = named || (w.find("plastic_dx9.fx:37") != std::string::npos && w.find("default_color.dds") != std::string::npos &&
                          w.find("--set ColorSampler=FILE") != std::string::npos);
    CHECK(named);
    CHECK(session.resources().find("ColorTexture")->source.find("placeholder") != std::string::npos);
    // --set on the sampler replaces the texture it reads.
    session.values().textures["ColorSampler"] = std::string(FXVIEW_SOURCE_EFFECTS_DIR) + "/../textures/checker.png";
    session.reload_textures();
    CHECK(session.resources().find("ColorTexture")->source.find("checker.png") != std::string::npos);
}

TEST_CASE("errors name the original file:line, the technique and the pass") {
    shared_context();
    const effect::Effect bad = effect::load_effect(kLegacy + "/bad_hlsl.fx", load_options());
    try {
        effect::compile_technique(bad, bad.techniques[0]);
        FAIL("bad_hlsl.fx compiled");
    } catch (const effect::EffectError& error) {
        const std::string message = error.what();
        CHECK(message.find("bad_hlsl.fx:7: error: 'undeclaredGain'") != std::string::npos);
        CHECK(message.find("technique Broken, pass p0") != std::string::npos);
    }
    try {
        effect::load_effect(kLegacy + "/cg_interface.cgfx", load_options());
        FAIL("an interface was accepted");
    } catch (const effect::EffectError& error) {
        CHECK(std::string(error.what()).find("cg_interface.cgfx:2: Cg interfaces are not supported") != std::string::npos);
    }
    // A name declared twice: an error at the second declaration (glslang crashed on this pair).
    try {
        effect::load_effect(kLegacy + "/duplicate_global.fx", load_options());
        FAIL("a redeclaration was accepted");
    } catch (const effect::EffectError& error) {
        CHECK(std::string(error.what()).find("duplicate_global.fx:4: 'Tint' is declared twice") != std::string::npos);
    }
    // A geometry program: skipped with a warning at its line; its technique fails alone.
    render::EffectSession geometry(kLegacy + "/cg_geometry.cgfx", load_options(), {});
    CHECK(geometry.technique() == "Plain");
    bool skipped = false, failed = false;
    for (const auto& w : geometry.warnings()) {
        skipped = skipped || w.find("cg_geometry.cgfx:5: warning: Cg geometry program (TRIANGLE") != std::string::npos;
        failed = failed || w.find("cg_geometry.cgfx:12: error: geometry programs are not supported") != std::string::npos;
    }
    CHECK(skipped);
    CHECK(failed);
    // One technique that does not translate: the effect opens with the other and says why.
    render::EffectSession partial(kLegacy + "/partial.fx", load_options(), {});
    CHECK(partial.technique() == "Good");
    REQUIRE(!partial.warnings().empty());
    CHECK(partial.warnings().back().find("partial.fx:8: error: PS has 0 uniform parameter(s)") != std::string::npos);
}

TEST_CASE("hot reload of a legacy file keeps the user's values") {
    shared_context();
    const std::string path = temp_path("reload_legacy.fx");
    const auto write = [&](const std::string& colour_expression) {
        std::ofstream out(path);
        out << "float4x4 Wvp : WorldViewProjection;\nfloat Gain = 0.25;\n"
               "float4 VS(float4 P : POSITION) : POSITION { return mul(P, Wvp); }\n"
               "float4 PS() : COLOR { return " << colour_expression << "; }\n"
               "technique T { pass p { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
    };
    write("float4(Gain, 0, 0, 1)");
    render::EffectSession session(path, load_options(), {});
    session.values().numbers["Gain"] = {0.5};
    gl::RenderTarget target({16, 16, 1, 0});
    const auto centre = [&] {
        session.render(scene::Scene{}, target);
        return target.read_color().pixel(8, 8);
    };
    CHECK(centre()[0] == 0.5f);
    write("float4(0, Gain, 0, 1) +");  // broken: the last good effect stays
    REQUIRE(session.reload().has_value());
    CHECK(centre()[0] == 0.5f);
    write("float4(0, Gain, 0, 1)");
    CHECK(!session.reload().has_value());
    CHECK(centre()[1] == 0.5f);  // the edited Gain survived both reloads
}

TEST_CASE("DirectX SDK and Cg Toolkit idioms: float4x3 World, ViewPosition, untyped cube samplers, VFACE, glstate, h4tex2D") {
    const effect::Effect dx = effect::load_effect(kLegacy + "/dx_sdk_idioms.fx", load_options());
    CHECK(parameter(dx, "World43").semantic == "WORLD");  // filled although float4x3 is no editable type
    CHECK(parameter(dx, "ViewPos").semantic == "CAMERAPOSITION");
    CHECK(parameter(dx, "Reflectivity").ui.max == 1.0);  // a float4 UIMax gives its first component
    CHECK(parameter(dx, "Env").type == "samplerCube");   // untyped, read with texCUBE
    CHECK(dx.find_texture("EnvTex")->files == std::vector<std::string>{"missing_sky.dds"});  // string name = ...
    CHECK(dx.techniques.size() == 1);  // the DX10 state objects and technique10 are skipped
    const std::string fragment = effect::assemble_stage(dx, dx.techniques[0].passes[0], effect::ShaderStage::Fragment);
    CHECK(fragment.find("gl_FrontFacing") != std::string::npos);  // VFACE
    CHECK(fragment.find("samplerCube Env") != std::string::npos);

    const effect::Effect cg = effect::load_effect(kLegacy + "/cg_toolkit.cgfx", load_options());
    CHECK(!cg.row_vectors);
    CHECK(parameter(cg, "fxview_glstate_mvp").semantic == "WORLDVIEWPROJECTION");
    CHECK(parameter(cg, "fxview_glstate_light0_position").semantic == "VIEWLIGHTPOSITION");
    CHECK(parameter(cg, "Decal").texture == "decalTex");  // uniform texture2D decalTex < ... >
    REQUIRE(cg.find_texture("decalTex") != nullptr);
    CHECK(cg.find_texture("decalTex")->files == std::vector<std::string>{"missing_decal.png"});

    const image::FloatImage reference = debug_view();
    CHECK(overlap(render_effect("dx_sdk_idioms.fx"), reference) > 0.98);
    const image::FloatImage toolkit = render_effect("cg_toolkit.cgfx");
    CHECK(overlap(toolkit, reference) > 0.98);
    CHECK(luminance(toolkit.pixel(44, 20)) > luminance(toolkit.pixel(20, 44)) + 0.05);  // lit towards the light
}

TEST_CASE("idioms of the real legacy corpus: Cg's varying, transposed matrix semantics, expression defaults, matrices set by name") {
    // Found by a measurement on 33 real files (docs/legacy-effects.md): basic_phong.cgfx failed on
    // `varying`; relief_mapping.cgfx's WorldViewProjectionTranspose multiplied vector first was taken
    // for row vectors (garbage on screen); scene_tonemap.fx's `= 1.0 / 2.2` was dropped to 0 (white);
    // CustomUI.fx's semantic-less matrices stayed zero (nothing drawn).
    const effect::Effect cg = effect::load_effect(kLegacy + "/cg_varying_transposed.cgfx", load_options());
    CHECK(!cg.row_vectors);  // mul(v, Mᵀ) counts as mul(M, v)
    CHECK(parameter(cg, "Gamma").default_value->numbers == std::vector<double>{1.0 / 2.2});
    const std::vector<double> tint = parameter(cg, "Tint").default_value->numbers;
    CHECK(tint.size() == 3);
    CHECK(tint[0] == doctest::Approx(0.8));
    CHECK(tint[1] == doctest::Approx(0.5));
    CHECK(tint[2] == doctest::Approx(0.5));
    const effect::Effect dx = effect::load_effect(kLegacy + "/dx_sdk_app_matrices.fx", load_options());
    CHECK(parameter(dx, "g_mWorldViewProjection").semantic == "WORLDVIEWPROJECTION");
    CHECK(parameter(dx, "g_mWorld").semantic == "WORLD");
    CHECK(parameter(dx, "MeshTextureSampler").ui.label == "Mesh texture");  // the texture object's UIName
    bool said = false;
    for (const auto& w : dx.warnings) said = said || w.find("g_mWorld has no semantic; fxview supplies it as WORLD by its name") != std::string::npos;
    CHECK(said);
    const image::FloatImage reference = debug_view();
    for (const std::string file : {"cg_varying_transposed.cgfx", "dx_sdk_app_matrices.fx"}) {
        CAPTURE(file);
        const image::FloatImage picture = render_effect(file);
        CHECK(overlap(picture, reference) > 0.98);
        CHECK(luminance(picture.pixel(44, 20)) > luminance(picture.pixel(20, 44)) + 0.05);  // lit towards the light
    }
    // VertexShader = null (the DirectX SDK's post-processing samples): DirectX's fixed-function
    // vertex stage puts the object where the debug view does and hands the pixel shader the mesh's
    // texture coordinates (its output adds them to red and green: not flat).
    const effect::Effect pp = effect::load_effect(kLegacy + "/pp_null_vertex.fx", load_options());
    CHECK(parameter(pp, "fxview_fixed_function_wvp").semantic == "WORLDVIEWPROJECTION");
    const image::FloatImage post = render_effect("pp_null_vertex.fx");
    CHECK(overlap(post, reference) > 0.98);
    CHECK(std::abs(post.pixel(20, 32)[0] - post.pixel(44, 32)[0]) > 0.1);
    // An expression that is no constant is said, not silently zero.
    const std::string odd = temp_path("odd_default.fx");
    {
        std::ifstream in(kLegacy + "/dx_sdk_app_matrices.fx");
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        text.insert(0, "float Odd = sqrt(2.0);\n");
        std::ofstream(odd) << text;
    }
    const effect::Effect with_odd = effect::load_effect(odd, load_options());
    said = false;
    for (const auto& w : with_odd.warnings) said = said || w.find("odd_default.fx:1: warning: the default of Odd is an expression fxview does not evaluate") != std::string::npos;
    CHECK(said);
}

TEST_CASE("which files are legacy: .cgfx always, .fx without GLSL blocks whose passes compile functions") {
    const std::string native = temp_path("native_compile.fx");
    {
        std::ofstream out(native);  // a native effect in CgFX spelling: `shader` blocks and `compile PROFILE name()`
        out << "#include \"standard.glsl\"\n"
               "shader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1); } }\n"
               "technique T { pass p { VertexShader = compile glslv StandardVS(); FragmentShader = compile glslf FS(); } }\n";
    }
    CHECK(!effect::load_effect(native, load_options()).legacy);
    CHECK(effect::load_effect(kLegacy + "/plastic_dx9.fx", load_options()).legacy);
    CHECK(effect::load_effect(kLegacy + "/plastic_cg.cgfx", load_options()).legacy);
}
