// A measured BRDF (grid CSV or MERL .binary, viewer/fit) as a 3D RGBA32F texture that shaders look
// up by angle: x = φo (0..180°), y = θo, z = θi (0..90°), texel centres at the grid's samples (GL row
// t = 0 holds θo = 0). Effects declare it as a sampler3D whose ResourceName is the data file.
#pragma once
#include "core/limits.hpp"
#include <string>

#include "texture/texture_data.hpp"

namespace fxview::render {

// True for files that hold a measured BRDF: ".binary" (MERL), or a CSV starting with the grid header.
bool is_measured_brdf_file(const std::string& path);

// Error unless the grid is uniform over θ 0..90° and φ 0..180° (the shader maps angles linearly).
texture::TextureData load_measured_brdf_texture(const std::string& path, const ResourceLimits& limits = {});

}  // namespace fxview::render
