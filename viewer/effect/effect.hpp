// The in-memory form of an effect file (docs/effect-format.md): parameters with annotations and
// semantics, named GLSL shader blocks, and techniques made of passes with render states.
// Parsing produces it; effect_program.hpp compiles it.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "effect/render_states.hpp"
#include "effect/source_map.hpp"
#include "texture/texture_data.hpp"

namespace fxview::effect {

// A constant written in the file: a number list, a boolean or a string.
struct Value {
    std::vector<double> numbers;  // scalars and vectors; booleans as 0/1
    std::string text;             // strings
    bool is_string = false;
};

struct Annotation {
    std::string type;  // as written: float, int, bool, string, ...
    std::string name;
    Value value;
    SourceLocation where;
};

// What the user interface should show for a parameter, from its annotations in any of the three
// spellings (NVIDIA UIName..., DXSAS SasUi..., Maya lower case).
struct UiHints {
    std::string label;
    std::string widget;  // slider, drag, color, checkbox, combo, vector, none, ...
    std::optional<double> min, max, step;
    std::string group;
    int order = 0;
    std::string unit;
    std::string help;
    std::vector<std::string> items;  // combo entries ("a|b|c" or "a,b,c")
    std::string at_least;            // UIAtLeast: a scalar parameter this one may not fall below
};

// How a sampler reads its texture (from annotations or a CgFX sampler_state block).
struct SamplerState {
    GLenum min_filter = GL_LINEAR_MIPMAP_LINEAR;
    GLenum mag_filter = GL_LINEAR;
    GLenum wrap_s = GL_REPEAT, wrap_t = GL_REPEAT, wrap_r = GL_REPEAT;
};

enum class TextureStorage { Native, Unorm8, Float16, Float32 };

// A texture the effect uses: loaded from a file (ResourceName) or a render target that passes
// draw into (declared `texture NAME : RENDERCOLORTARGET`).
struct TextureResource {
    std::string name;
    SourceLocation where;
    std::vector<std::string> files;  // as written; six names for a cube from separate faces
    texture::TextureType type = texture::TextureType::Tex2D;
    TextureStorage storage = TextureStorage::Native;
    bool srgb = false;
    int depth = 0;  // 3D from an image: the number of slices stacked top to bottom (0: not given)
    bool render_target = false;
    glm::vec2 viewport_ratio{1.0f};   // render targets: size relative to the frame
    std::optional<glm::ivec2> dimensions;  // render targets: fixed size instead
    std::vector<Annotation> annotations;
};

struct Parameter {
    std::string type;  // GLSL type: float, vec3, int, bool, mat4, ...
    std::string name;
    int array_size = 0;    // 0: not an array
    std::string semantic;  // upper case, empty if none
    std::vector<Annotation> annotations;
    std::optional<Value> default_value;
    UiHints ui;
    std::string texture;   // samplers: the TextureResource they read
    SamplerState sampler;  // samplers: filtering and wrapping
    SourceLocation where;
};

// A uniform block of a translated (Cg/HLSL) stage: where each parameter sits in it, as SPIRV-Cross
// reflects the std140 layout of the `$Global` constant buffer.
struct UniformBlockMember {
    std::string parameter;  // the effect parameter it holds
    enum class Kind { Float, Int, UInt } kind = Kind::Float;
    std::uint32_t offset = 0;
    int vector_size = 1, columns = 1;  // SPIR-V's view: a matrix is `columns` vectors of `vector_size`
    int array_size = 0;                // 0: not an array
    std::uint32_t array_stride = 0, matrix_stride = 0;
    bool row_major = false;
};
struct UniformBlockLayout {
    std::uint32_t binding = 0;
    std::uint32_t size = 0;
    std::vector<UniformBlockMember> members;
};

struct ShaderBlock {
    std::string name;
    std::string code;  // GLSL with #line directives
    SourceLocation where;
    // Stages translated from Cg/HLSL (viewer/legacy) are complete GLSL programs whose parameters sit
    // in a uniform block; a stage that failed to translate keeps its messages (file:line each) so that
    // only its technique fails, as a native technique whose GLSL does not compile.
    bool complete = false;
    std::optional<UniformBlockLayout> uniform_block;
    std::string translation_errors;
};

// A legacy script's LoopByCount=PARAM runs its passes PARAM times: they are unrolled to the most the
// parameter allows, and each copy runs only while the parameter's current value reaches its iteration.
struct LoopCondition {
    std::string parameter;
    int iteration = 1;  // 1-based
};

struct Pass {
    std::string name;
    std::map<ShaderStage, std::string> shaders;  // stage -> shader block name
    RenderStates states;
    SourceLocation where;
    std::vector<LoopCondition> runs_if;  // all must hold; empty: always runs
    // Its clear came from the script before the loop it sits in: when the loop's value skips it,
    // the next pass that runs clears instead (a clear inside the loop body is skipped with it).
    bool carries_clear = false;
};

struct Technique {
    std::string name;
    std::vector<Pass> passes;
    std::vector<Annotation> annotations;
    SourceLocation where;

    // What the user interface shows: its `string UIName` annotation, else its name.
    std::string label() const {
        for (const auto& a : annotations)
            if (a.name == "UIName" && a.value.is_string && !a.value.text.empty()) return a.value.text;
        return name;
    }
};

// `plugin NAME < string Type = "brdf-fit"; ... >;`: a built-in plugin the effect runs on its own
// parameters and textures (docs/plugins.md). The file can only name a type compiled into fxview.
struct PluginDeclaration {
    std::string name;
    std::vector<Annotation> annotations;  // Type and the type's own settings
    SourceLocation where;

    const Annotation* find(const std::string& annotation) const;
    // The annotation's string; empty when absent. EffectError at the annotation if it is not a string.
    std::string text(const std::string& annotation) const;
};

struct Effect {
    std::string path;
    SourceMap sources;          // the effect file and its includes
    std::string globals;        // top-level GLSL (functions, structs, consts) with #line directives
    std::vector<Parameter> parameters;
    std::vector<TextureResource> textures;
    std::vector<ShaderBlock> shaders;
    std::vector<Technique> techniques;
    std::vector<PluginDeclaration> plugins;
    // What the effect may read (its folder, the search roots, folders the user allowed) and how
    // much: textures and data files are loaded under the same rules as its includes.
    FileAccessPolicy access;
    ResourceLimits limits;
    // Legacy (Cg/HLSL) effects: how their matrices multiply vectors. Row vectors (`mul(v, M)`,
    // DirectX) get every matrix transposed from fxview's column-vector convention.
    bool legacy = false;
    bool row_vectors = false;
    // Things the loader could not honour but that do not stop the effect (unknown render states,
    // skipped DX10 techniques, missing textures replaced by placeholders), each "file:line: message".
    std::vector<std::string> warnings;

    const Parameter* find_parameter(const std::string& name) const;
    const ShaderBlock* find_shader(const std::string& name) const;
    const Technique* find_technique(const std::string& name) const;
    // The technique an effect opens on: the one annotated `bool Default = true`, else the first.
    const Technique& default_technique() const;
    const TextureResource* find_texture(const std::string& name) const;
    const PluginDeclaration* find_plugin(const std::string& name) const;
};

}  // namespace fxview::effect
