#include "legacy/legacy_effect.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "core/text.hpp"
#include "effect/lexer.hpp"
#include "effect/parser.hpp"
#include "effect/semantics.hpp"
#include "legacy/entry_wrapper.hpp"
#include "legacy/buffer_blocks.hpp"
#include "legacy/glslang_process.hpp"
#include "legacy/hlsl_translator.hpp"
#include "legacy/legacy_parameters.hpp"
#include "legacy/legacy_source.hpp"
#include "legacy/pass_script.hpp"

namespace fxview::legacy {
namespace {

using effect::ShaderStage;

// The convention: the user's override, the effect's annotation, the file's use of mul(), its kind.
bool row_vectors_for(const effect::Effect& effect, const LegacySource& source, const std::string& override_value) {
    const auto parse = [](const std::string& text, bool& row) {
        const std::string t = to_lower(text);
        if (t == "row" || t == "row-vector" || t == "row-vectors" || t == "directx") { row = true; return true; }
        if (t == "column" || t == "column-vector" || t == "column-vectors" || t == "opengl") { row = false; return true; }
        return false;
    };
    bool row = false;
    if (!override_value.empty()) {
        if (!parse(override_value, row)) throw UsageError("--matrix-convention must be row or column, not '" + excerpt(override_value) + "'");
        return row;
    }
    for (const auto& a : source.effect_annotations)
        if (to_lower(a.name) == "matrixconvention" && a.value.is_string) {
            if (!parse(a.value.text, row))
                throw effect::EffectError(a.where, "MatrixConvention must be \"row\" or \"column\", not '" + excerpt(a.value.text) + "'");
            return row;
        }
    if (source.row_vector_uses != source.column_vector_uses) return source.row_vector_uses > source.column_vector_uses;
    return lower_extension(effect.path) != ".cgfx";
}

const FunctionSignature* find_function(const LegacySource& source, const CompileStatement& statement) {
    const auto [begin, end] = source.functions.equal_range(statement.function);
    const FunctionSignature* first = nullptr;
    for (auto it = begin; it != end; ++it) {
        if (!first) first = &it->second;
        const auto uniforms = std::count_if(it->second.parameters.begin(), it->second.parameters.end(), [](const auto& p) { return p.uniform; });
        if (static_cast<size_t>(uniforms) == statement.arguments.size()) return &it->second;
    }
    return first;
}

// DirectX's fixed-function vertex stage for a pass with `VertexShader = NULL` (the DirectX SDK's
// post-processing samples): the position through WorldViewProjection (the uniform
// fxview_fixed_function_wvp, supplied by the scene), and what the pixel program reads: texture
// coordinates from the mesh's first set, colours white. Empty, with `error` set, where the pixel
// program's inputs carry no semantics (a structure).
std::string fixed_function_vertex(const FunctionSignature& fragment, bool row_vectors, std::string& error) {
    std::string outputs, body;
    for (const auto& p : fragment.parameters) {
        if (p.uniform || p.output) continue;
        const std::string semantic = to_lower(p.semantic);
        if (semantic.empty()) {
            error = "VertexShader = NULL: the pixel program's input " + p.name + " has no semantic (fxview's fixed-function stage writes TEXCOORDn and COLORn)";
            return {};
        }
        if (semantic == "vpos" || semantic == "vface" || semantic.rfind("sv_", 0) == 0) continue;
        const std::string name = "fxview_out_" + p.name;
        outputs += ", out " + p.type + " " + name + " : " + p.semantic;
        const std::string source = semantic.rfind("texcoord", 0) == 0 ? "fxview_uv" : semantic.rfind("color", 0) == 0 ? "float4(1, 1, 1, 1)" : "float4(0, 0, 0, 0)";
        const int components = std::isdigit(static_cast<unsigned char>(p.type.back())) ? p.type.back() - '0' : 1;
        body += name + " = (" + p.type + ")(" + source + ")" + std::string(".xyzw").substr(0, static_cast<size_t>(components) + 1) + "; ";
    }
    return "float4x4 fxview_fixed_function_wvp;\nvoid fxview_vertex_entry(float4 fxview_position : POSITION, float4 fxview_uv : TEXCOORD0, out float4 fxview_clip : SV_Position" +
           outputs + ") { fxview_clip = " + (row_vectors ? "mul(fxview_position, fxview_fixed_function_wvp)" : "mul(fxview_fixed_function_wvp, fxview_position)") +
           "; " + body + "}\n";
}

// Returns whether the pass's own script chose its render targets.
bool add_pass(effect::Effect& effect, const LegacySource& source, effect::Technique& technique, const LegacyPass& legacy, int file_lines,
              SpirvCache& cache) {
    effect::Pass pass;
    pass.name = legacy.name;
    pass.where = legacy.where;
    pass.states = legacy.states;
    const bool sets_targets = apply_pass_script(pass, legacy.annotations, effect, effect.warnings);
    std::vector<StageRequest> requests;
    std::string errors;
    for (const auto& statement : legacy.programs) {
        if (statement.stage == ShaderStage::Geometry) {
            errors += statement.where.str() + ": error: geometry programs are not supported (" + excerpt(statement.function) +
                      "); this technique does not open\n";
            continue;
        }
        const FunctionSignature* function = find_function(source, statement);
        if (!function) {
            errors += statement.where.str() + ": error: unknown function '" + excerpt(statement.function) + "' in the compile statement\n";
            continue;
        }
        const std::string entry = statement.stage == ShaderStage::Vertex ? "fxview_vertex_entry" : statement.stage == ShaderStage::Fragment ? "fxview_fragment_entry" : "fxview_geometry_entry";
        std::string wrapper_error;
        const std::string wrapper = entry_wrapper(*function, statement, entry, wrapper_error);
        if (!wrapper_error.empty()) {
            errors += statement.where.str() + ": error: " + wrapper_error + "\n";
            continue;
        }
        const char* kind = statement.stage == ShaderStage::Vertex ? "vertex program " : statement.stage == ShaderStage::Fragment ? "fragment program " : "geometry program ";
        requests.push_back({statement.stage, source.code + "\n" + wrapper, entry, statement.where, kind + statement.function});
    }
    bool has_vertex = std::any_of(legacy.programs.begin(), legacy.programs.end(), [](const auto& s) { return s.stage == ShaderStage::Vertex; });
    const auto fragment = std::find_if(legacy.programs.begin(), legacy.programs.end(), [](const auto& s) { return s.stage == ShaderStage::Fragment; });
    if (!has_vertex && legacy.fixed_function_vertex && fragment != legacy.programs.end())
        if (const FunctionSignature* function = find_function(source, *fragment)) {
            std::string error;
            const std::string stage = fixed_function_vertex(*function, effect.row_vectors, error);
            if (!error.empty()) errors += legacy.where.str() + ": error: " + error + "\n";
            requests.push_back({ShaderStage::Vertex, source.code + "\n" + stage, "fxview_vertex_entry", legacy.where, "fixed-function vertex stage"});
            has_vertex = true;
            if (!effect.find_parameter("fxview_fixed_function_wvp")) {
                effect::Parameter wvp;
                wvp.name = "fxview_fixed_function_wvp";
                wvp.type = "mat4";
                wvp.semantic = "WORLDVIEWPROJECTION";
                wvp.where = legacy.where;
                effect.parameters.push_back(std::move(wvp));
            }
        }
    if (!has_vertex || fragment == legacy.programs.end())
        errors += legacy.where.str() + ": error: pass " + legacy.name + " needs a vertex and a fragment program (fixed-function passes are not supported)\n";
    TranslatedPass translated;
    if (errors.empty()) {
        translated = translate_pass(requests, file_lines, [&](int line) {
            // Offsets of the code are offsets of the preprocessed text: SourceMap knows their origin.
            return effect.sources.locate_line(line);
        }, cache);
        errors = translated.errors;
    }
    for (const ShaderStage stage : {ShaderStage::Vertex, ShaderStage::Fragment}) {
        effect::ShaderBlock block;
        block.name = technique.name + "/" + pass.name + "/" + effect::stage_name(stage);
        block.where = pass.where;
        block.complete = true;
        if (errors.empty()) {
            block.code = translated.stages[stage].glsl;
            block.uniform_block = translated.stages[stage].uniform_block;
        } else if (stage == ShaderStage::Vertex) {
            block.translation_errors = errors;  // once per pass
        }
        pass.shaders[stage] = block.name;
        effect.shaders.push_back(std::move(block));
    }
    technique.passes.push_back(std::move(pass));
    return sets_targets;
}

}  // namespace

bool is_legacy_effect(const effect::Effect& effect) {
    if (lower_extension(effect.path) == ".cgfx") return true;
    if (lower_extension(effect.path) != ".fx") return false;
    effect::Lexer lexer(effect.sources.text());
    bool compiles = false;
    effect::Token before, last;  // `shader NAME {` is a native GLSL block too
    for (effect::Token t = lexer.next(); t.kind != effect::TokenKind::End; t = lexer.next()) {
        if (t.kind == effect::TokenKind::Punct && t.text == "{" && before.kind == effect::TokenKind::Identifier && before.text == "shader" && last.kind == effect::TokenKind::Identifier)
            return false;
        before = last;
        last = t;
        if (t.kind != effect::TokenKind::Identifier) continue;
        if (t.text == "GLSLShader") return false;
        if (t.text == "compile") compiles = true;
    }
    return compiles;
}

// glslang's HLSL parser descends recursively: nesting is bounded before it sees the code, as
// nothing real nests deeper than a few dozen levels.
void check_nesting(const effect::Effect& effect, const std::string& code) {
    constexpr int kMaxDepth = 256;
    int depth = 0;
    bool in_string = false;
    for (size_t i = 0; i < code.size(); ++i) {
        const char c = code[i];
        if (c == '"') in_string = !in_string;
        if (in_string || c == '\n') { if (c == '\n') in_string = false; continue; }
        if (c == '(' || c == '[' || c == '{') ++depth;
        if (c == ')' || c == ']' || c == '}') depth = std::max(0, depth - 1);
        if (depth > kMaxDepth) throw effect::EffectError(effect.sources.locate(i), "brackets nested deeper than " + std::to_string(kMaxDepth) + " levels");
    }
}

// Every stage compile reads the whole file: the compile-bytes budget bounds their sum, as for native effects.
void check_compile_budget(const effect::Effect& effect, const LegacySource& source) {
    std::int64_t compiled = 0;
    std::set<std::string> programs;  // stage, function and arguments: each compiled once
    for (const auto& technique : source.techniques)
        for (const auto& pass : technique.passes) {
            for (const auto& p : pass.programs) {
                std::string key = std::to_string(static_cast<int>(p.stage)) + " " + p.function;
                for (const auto& a : p.arguments) key += "\n" + a;
                if (programs.insert(key).second) compiled += static_cast<std::int64_t>(source.code.size());
            }
            if (compiled > effect.limits.compile_bytes)
                throw effect::EffectError(pass.where, "technique " + technique.name + " brings the Cg/HLSL compiled for this effect to " +
                                                          std::to_string(compiled) + " bytes, over the budget compile-bytes = " +
                                                          std::to_string(effect.limits.compile_bytes) + " (raise it with --limit compile-bytes=N)");
        }
}

void load_legacy_effect(effect::Effect& effect, const std::string& matrix_convention) {
    effect.sources.replace_text(preprocess_legacy(effect));
    std::vector<std::string> buffer_warnings;
    effect.sources.replace_text(rewrite_buffer_blocks(effect.sources.text(), effect.sources, buffer_warnings));
    check_nesting(effect, effect.sources.text());
    const LegacySource source = parse_legacy_source(effect);
    check_compile_budget(effect, source);
    effect.legacy = true;
    effect.row_vectors = row_vectors_for(effect, source, matrix_convention);
    effect.warnings = buffer_warnings;
    effect.warnings.insert(effect.warnings.end(), source.warnings.begin(), source.warnings.end());
    effect.textures = source.textures;
    for (const auto& global : source.globals) add_parameter(effect, global);
    for (auto& p : effect.parameters) {  // UIAtLeast must name another scalar (as native effects check)
        if (p.ui.at_least.empty()) continue;
        const effect::Parameter* other = effect.find_parameter(p.ui.at_least);
        if (!other || other == &p || effect::component_count(other->type) != 1 || other->array_size > 0 || effect::component_count(p.type) != 1 ||
            p.array_size > 0 || !other->semantic.empty() || !p.semantic.empty()) {
            effect.warnings.push_back(p.where.str() + ": warning: UIAtLeast of " + p.name + " names no other scalar parameter; ignored");
            p.ui.at_least.clear();
        }
    }
    const int file_lines = static_cast<int>(std::count(source.code.begin(), source.code.end(), '\n')) + 1;
    SpirvCache cache;
    for (const auto& legacy : source.techniques) {
        effect::Technique technique;
        technique.name = legacy.name;
        technique.where = legacy.where;
        technique.annotations = legacy.annotations;
        std::vector<bool> sets_targets;
        for (const auto& pass : legacy.passes) sets_targets.push_back(add_pass(effect, source, technique, pass, file_lines, cache));
        apply_technique_script(technique, sets_targets, effect, effect.warnings);
        effect.techniques.push_back(std::move(technique));
    }
    if (effect.techniques.empty()) {
        throw effect::EffectError({effect.path, 1}, source.warnings.empty() ? "the effect defines no technique"
                                                                            : "the effect defines no technique fxview can run (" + source.warnings.front() + ")");
    }
}

}  // namespace fxview::legacy
