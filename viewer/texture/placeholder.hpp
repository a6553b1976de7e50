// Textures that stand in for missing files of legacy effects (the NVIDIA library's .dds files are
// often absent or not redistributable): suited to the sampler's type and to what its name says.
#pragma once
#include <string>

#include "texture/texture_data.hpp"

namespace fxview::texture {

// A flat normal map for names with "normal" or "bump", a mid-grey height map for "height",
// "bump" or "displace"... in short: 2D: a grey checker (or flat normal/black/white by name),
// cube: uniform grey, 3D: value noise, 1D: a grey ramp. RGBA8, with no mip levels.
TextureData placeholder_texture(TextureType type, const std::string& name);

// What the placeholder shows, for the warning: "checker", "flat normal", ...
std::string placeholder_kind(TextureType type, const std::string& name);

}  // namespace fxview::texture
