// Compiling a technique: one GL program per pass, assembled from the parameter declarations, the
// shared top-level GLSL and the pass's shader blocks; active uniforms are reflected and checked
// against the declarations, and bound each draw from parameter values or SAS semantics.
#pragma once
#include <memory>
#include <vector>

#include "effect/effect.hpp"
#include "effect/parameter_values.hpp"
#include "effect/semantics.hpp"
#include "gl/objects.hpp"

namespace fxview::effect {

struct BoundUniform {
    GLint location = -1;
    GLenum type = 0;
    GLint array_size = 1;
    const Parameter* parameter = nullptr;
    int texture_unit = -1;  // samplers: the unit their texture is bound to
};

// The uniform buffer of a translated stage, refilled from the parameters before each draw.
struct BoundUniformBlock {
    const UniformBlockLayout* layout = nullptr;
    std::vector<const Parameter*> parameters;  // per member of the layout
    gl::Buffer buffer;
};

struct CompiledPass {
    const Pass* pass = nullptr;
    // Shared between passes of one technique whose stages are the same (a legacy loop's copies).
    std::shared_ptr<gl::Program> program;
    std::vector<BoundUniform> uniforms;
    std::vector<BoundUniformBlock> blocks;
    bool row_vectors = false;  // the effect's matrix convention (Effect::row_vectors)
    int texture_units = 0;
};

struct CompiledTechnique {
    const Technique* technique = nullptr;
    std::vector<CompiledPass> passes;
};

// The GLSL of one stage of a pass exactly as it goes to the driver (`fxview check --dump` prints it).
std::string assemble_stage(const Effect& effect, const Pass& pass, ShaderStage stage);

// Throws EffectError whose message holds every compiler message mapped to `file:line`.
CompiledTechnique compile_technique(const Effect& effect, const Technique& technique);

// Compiler messages of several techniques ("file:line: message [technique T, pass P, ...]" a line)
// with repeats folded: code shared by techniques (top-level GLSL, a .brdf file's BRDF()) fails the
// same way in each, and is reported once as "file:line: message [techniques A, B, C]".
std::string fold_repeated_messages(const std::string& lines);

// The bytes of a translated stage's uniform block: every member from its parameter's value or
// semantic, matrices transposed for row-vector effects. Exposed for tests of the packing.
std::vector<std::byte> pack_uniform_block(const UniformBlockLayout& layout, const std::vector<const Parameter*>& parameters,
                                          const ParameterValues& values, const FrameContext& frame, bool row_vectors);

// Sets every non-sampler uniform of the pass: semantics from `frame`, the rest from `values`.
// (Samplers have fixed units; the renderer binds their textures.)
void bind_uniforms(const CompiledPass& pass, const ParameterValues& values, const FrameContext& frame);

}  // namespace fxview::effect
