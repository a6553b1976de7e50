// Textures that stand in for missing files of legacy effects (the NVIDIA library's .dds files are
// often absent or not redistributable): suited to the sampler's type and to what its name says.
#pragma once
#include <string>

#include "texture/texture_data.hpp"

namespace fxview::texture {

// A flat normal map for names with "normal" or "bump", a mid-grey height map for "height",
// "bump" or "displace"... in short: 2D: a grey checker (or flat normal/black/white by name),
// cube: uniform grey, 3D: value noise, 1D: a grey ramp. RGBA8, with no mip levels.
// A missing Radiance file (`file` ending .hdr or .rgbe), which shaders decode as RGBE themselves
// (rgb · 2^(255·a − 128)), gets alpha 128/255: exponent 0, so that the stand-in decodes to its own
// grey instead of 1e38.
TextureData placeholder_texture(TextureType type, const std::string& name, const std::string& file = "");

// What the placeholder shows, for the warning: "grey checker", "flat normal map", ...
std::string placeholder_kind(TextureType type, const std::string& name, const std::string& file = "");

}  // namespace fxview::texture
