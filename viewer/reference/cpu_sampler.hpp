// Texture sampling on the CPU by OpenGL's rules (GL 4.5 core spec §8.14): nearest and linear
// filtering on the base level, the wrap modes REPEAT, CLAMP_TO_EDGE and MIRRORED_REPEAT, sRGB
// decoding before filtering, t = 0 at the image's bottom row (fxview uploads images top row up).
// References use it to read the same texture data the GPU samples.
#pragma once
#include <glm/glm.hpp>

#include "effect/effect.hpp"
#include "texture/texture_data.hpp"

namespace fxview::reference {

// Samples a 2D texture at `uv`. Mipmapped minification filters are not reproduced (they depend on
// screen-space derivatives): they throw Error so that a reference never silently differs.
glm::dvec4 sample_2d(const texture::TextureData& texture, const effect::SamplerState& sampler, bool srgb, glm::dvec2 uv);

// A 3D texture at `str` (GL's s, t, r; r = 0 at slice 0), trilinear or nearest on the base level.
// `footprint_spread` (optional) receives the largest max - min per channel of the texels filtered.
glm::dvec4 sample_3d(const texture::TextureData& texture, const effect::SamplerState& sampler, bool srgb, glm::dvec3 str,
                     double* footprint_spread = nullptr);

struct CubeSample {
    glm::dvec4 value;
    // At a cube corner, where GL leaves the texel of the missing neighbour to the implementation, the
    // largest spread (max - min per channel) of the texels around; else 0.
    double seam_spread = 0;
    // The spread (max - min per channel, the largest) of the texels a linear filter mixed: GL filters
    // with an implementation's sub-texel precision (llvmpipe: 8 bits), which moves the value by up
    // to this over 256.
    double footprint_spread = 0;
};

// Samples a cube map in `direction` by GL's face selection (spec table 8.19) and the base level's
// nearest or linear filter, seamless across face edges (fxview enables GL_TEXTURE_CUBE_MAP_SEAMLESS
// on every context); faces are stored in GL's row order (row 0 is t = 0).
CubeSample sample_cube(const texture::TextureData& texture, const effect::SamplerState& sampler, bool srgb, glm::dvec3 direction);

}  // namespace fxview::reference
