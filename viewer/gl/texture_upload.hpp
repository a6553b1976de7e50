// Creating GL textures from texture::TextureData: immutable storage of the right target (1D, 2D,
// cube) and internal format, all given mip levels (or generated ones), rows flipped so that the
// image's top is t = 1 as OpenGL expects (cube faces keep their rows: GL's cube convention
// already puts the first row at the top of each face).
#pragma once
#include "gl/objects.hpp"
#include "texture/texture_data.hpp"

namespace fxview::gl {

struct TextureUpload {
    bool srgb = false;             // 8-bit colour data encoded in sRGB: sample as linear
    bool generate_mipmaps = true;  // when the data has a single level and is uncompressed
};

GLenum texture_target(texture::TextureType type);
Texture upload_texture(const texture::TextureData& data, const TextureUpload& options);

// Reads back one level of one face (all slices of a 3D level) as RGBA float, top row first.
std::vector<float> download_texture(GLuint texture, texture::TextureType type, int face, int level, int width, int height,
                                    int depth = 1);

}  // namespace fxview::gl
