// Cg/HLSL stages to GLSL 4.5 through the libraries: glslang's HLSL front end (DX9-compatible
// samplers and semantics) makes SPIR-V, SPIRV-Cross writes GLSL. Between the two, the stages of a
// pass are joined by their semantics (not by declaration order): vertex inputs take fxview's mesh
// attributes, POSITION becomes gl_Position, varyings share locations by semantic, COLORn and DEPTH
// become the fragment outputs; the `$Global` constant buffer becomes one uniform block per stage
// whose layout is reflected for the application to fill.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "effect/effect.hpp"

namespace fxview::legacy {

struct StageRequest {
    effect::ShaderStage stage = effect::ShaderStage::Vertex;
    std::string code;   // whole Cg/HLSL text, the generated entry appended after the file's lines
    std::string entry;  // the generated entry function
    effect::SourceLocation where;  // the compile statement: where errors in the generated entry go
    std::string program;           // for messages: "vertex program std_VS"
};

struct TranslatedStage {
    std::string glsl;
    std::optional<effect::UniformBlockLayout> uniform_block;
};

struct TranslatedPass {
    std::map<effect::ShaderStage, TranslatedStage> stages;
    std::string errors;  // "file:line: message" lines; empty when every stage translated
};

// SPIR-V of stages already compiled for an effect, by stage and generated entry: passes that share
// a program (a screen-quad vertex program) compile it once.
struct SpirvCache {
    struct Entry {
        std::vector<unsigned> spirv;
        std::string errors;
    };
    std::map<std::string, Entry> entries;
};

// `locate` maps a 1-based line of the code to its file:line (the generated entry's lines are past
// `file_lines` and go to the compile statement). Stage requests' code must be the same file text
// (plus its entry) for every call that shares `cache`.
TranslatedPass translate_pass(const std::vector<StageRequest>& stages, int file_lines,
                              const std::function<effect::SourceLocation(int line)>& locate, SpirvCache& cache);

// The canonical form of a varying semantic: upper case, a missing index as 0, SV_Target as COLOR.
std::string canonical_semantic(const std::string& semantic);

}  // namespace fxview::legacy
