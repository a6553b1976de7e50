// A legacy effect (CgFX with Cg, DirectX 9 .fx with HLSL) read at the effect level: its globals
// with annotations and semantics, textures and sampler states, techniques and passes with their
// `compile PROFILE entry(arguments)` statements, and the shader code with all effect-only syntax
// blanked out line for line, so that a line of the code is the same line of the preprocessed file.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "effect/effect.hpp"

namespace fxview::legacy {

struct FunctionParameter {
    bool uniform = false;  // bound by the compile statement's arguments
    bool output = false;   // out or inout
    std::string type;
    std::string name;
    std::string semantic;  // as written, empty if none
    std::string declaration;  // as written, without `uniform` and default value: "in float4 P : POSITION"
};

struct FunctionSignature {
    std::string name;
    std::string return_type;
    std::string return_semantic;  // ": COLOR" as written, or empty
    std::vector<FunctionParameter> parameters;
    effect::SourceLocation where;
};

struct CompileStatement {
    effect::ShaderStage stage = effect::ShaderStage::Vertex;
    std::string profile;
    std::string function;
    std::vector<std::string> arguments;  // expressions, as written
    effect::SourceLocation where;
};

struct LegacyPass {
    std::string name;
    effect::SourceLocation where;
    std::vector<CompileStatement> programs;
    bool fixed_function_vertex = false;  // VertexShader = NULL: DirectX's fixed-function vertex stage
    effect::RenderStates states;
    std::vector<effect::Annotation> annotations;
};

struct LegacyTechnique {
    std::string name;
    effect::SourceLocation where;
    std::vector<effect::Annotation> annotations;
    std::vector<LegacyPass> passes;
};

struct LegacyGlobal {
    std::string type;  // as written: float4x4, half3, sampler2D, ...
    std::string name;
    int array_size = 0;
    std::string semantic;  // as written, empty if none
    std::vector<effect::Annotation> annotations;
    std::optional<effect::Value> default_value;  // numbers in the file's order (matrices row by row)
    std::string texture;                          // samplers: the texture of their sampler_state
    effect::SamplerState sampler;
    effect::SourceLocation where;
};

struct LegacySource {
    std::string code;  // Cg/HLSL, line for line with the preprocessed file
    std::vector<LegacyGlobal> globals;
    std::vector<effect::TextureResource> textures;
    std::vector<LegacyTechnique> techniques;
    std::multimap<std::string, FunctionSignature> functions;
    std::vector<effect::Annotation> effect_annotations;  // those of the STANDARDSGLOBAL parameter
    std::vector<std::string> warnings;                   // "file:line: message"
    // mul(M, v) and mul(v, M) with M a matrix-typed name: how the file multiplies (docs/legacy-effects.md).
    int column_vector_uses = 0, row_vector_uses = 0;
};

// Reads the effect level of `effect.sources` (already preprocessed). EffectError at file:line for
// syntax the translation does not support (Cg interfaces, shader variables, malformed blocks).
LegacySource parse_legacy_source(const effect::Effect& effect);

}  // namespace fxview::legacy
