// Loading texture files into TextureData, chosen by extension:
//   .png .jpg .jpeg .bmp .tga  through stb_image (RGBA8)      .hdr our own reader (RGBA32F; hdr_file.cpp)
//   .exr through tinyexr (RGBA32F)                           .dds (see dds_file.cpp)
//   .ftxt, the float text format of the original ShaderViewer (see ftxt_file.cpp)
// Every failure throws fxview::Error naming the file (and line, for text formats).
#pragma once
#include <string>

#include "core/limits.hpp"
#include "texture/texture_data.hpp"

namespace fxview::texture {

// Sizes a file claims are checked against `limits` (data-file-bytes, texture-dimension,
// texture-bytes) before anything is decoded or allocated.
TextureData load_texture_file(const std::string& path, const ResourceLimits& limits = {});

TextureData load_stb_image(const std::string& path, const ResourceLimits& limits = {});
TextureData load_exr_texture(const std::string& path, const ResourceLimits& limits = {});
TextureData load_hdr(const std::string& path, const ResourceLimits& limits = {});  // Radiance RGBE (hdr_file.cpp)
TextureData load_dds(const std::string& path, const ResourceLimits& limits = {});
TextureData load_ftxt(const std::string& path, const ResourceLimits& limits = {});

// One image holding a cube map as a cross: a vertical cross when taller than wide (3x4 faces,
// -Z stored upside down), else a horizontal cross (4x3 faces). Faces must be equal squares.
TextureData split_cube_cross(const TextureData& cross);

// A 1D texture from an image one pixel high.
TextureData as_1d(const TextureData& image);
// A 3D texture from an image holding `depth` equal slices stacked top to bottom.
TextureData as_3d(const TextureData& image, int depth);

}  // namespace fxview::texture
