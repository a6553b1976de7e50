#include "gl/texture_upload.hpp"

#include <algorithm>
#include <bit>

#include "core/error.hpp"

namespace fxview::gl {

using texture::PixelFormat;
using texture::TextureType;

GLenum texture_target(TextureType type) {
    switch (type) {
        case TextureType::Tex1D: return GL_TEXTURE_1D;
        case TextureType::Tex2D: return GL_TEXTURE_2D;
        case TextureType::Tex3D: return GL_TEXTURE_3D;
        case TextureType::Cube: return GL_TEXTURE_CUBE_MAP;
    }
    return GL_TEXTURE_2D;
}

namespace {

GLenum internal_format(PixelFormat format, bool srgb) {
    switch (format) {
        case PixelFormat::RGBA8: return srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
        case PixelFormat::RGBA16F: return GL_RGBA16F;
        case PixelFormat::RGBA32F: return GL_RGBA32F;
        case PixelFormat::BC1: return srgb ? GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT : GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
        case PixelFormat::BC2: return srgb ? GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT : GL_COMPRESSED_RGBA_S3TC_DXT3_EXT;
        case PixelFormat::BC3: return srgb ? GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT : GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
    }
    return GL_RGBA8;
}

GLenum pixel_type(PixelFormat format) {
    return format == PixelFormat::RGBA8 ? GL_UNSIGNED_BYTE : format == PixelFormat::RGBA16F ? GL_HALF_FLOAT : GL_FLOAT;
}

}  // namespace

Texture upload_texture(const texture::TextureData& source, const TextureUpload& options) {
    if (source.faces.empty() || source.faces[0].empty()) throw Error(source.source + ": empty texture");
    const bool compressed = texture::is_compressed(source.format);
    if (compressed && !GLAD_GL_EXT_texture_compression_s3tc)
        throw Error(source.source + ": the GL driver lacks EXT_texture_compression_s3tc for " + texture::format_name(source.format));
    texture::TextureData data = source;
    if (data.type != TextureType::Cube) texture::flip_vertically(data);

    const GLenum target = texture_target(data.type);
    const int width = data.width(), height = data.height(), depth = data.depth();
    const bool generate = options.generate_mipmaps && data.levels() == 1 && !compressed;
    const int levels = generate ? std::bit_width(static_cast<unsigned>(std::max({width, height, depth}))) : data.levels();
    Texture texture = create_texture(target);
    const GLuint name = texture.get();
    const GLenum format = internal_format(data.format, options.srgb);
    if (target == GL_TEXTURE_1D) glTextureStorage1D(name, levels, format, width);
    else if (target == GL_TEXTURE_3D) glTextureStorage3D(name, levels, format, width, height, depth);
    else glTextureStorage2D(name, levels, format, width, height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (size_t face = 0; face < data.faces.size(); ++face)
        for (size_t level = 0; level < data.faces[face].size(); ++level) {
            const texture::Level& l = data.faces[face][level];
            const auto m = static_cast<GLint>(level);
            if (compressed) {
                const auto size = static_cast<GLsizei>(l.bytes.size());
                if (target == GL_TEXTURE_CUBE_MAP)
                    glCompressedTextureSubImage3D(name, m, 0, 0, static_cast<GLint>(face), l.width, l.height, 1, format, size, l.bytes.data());
                else if (target == GL_TEXTURE_3D)
                    glCompressedTextureSubImage3D(name, m, 0, 0, 0, l.width, l.height, l.depth, format, size, l.bytes.data());
                else
                    glCompressedTextureSubImage2D(name, m, 0, 0, l.width, l.height, format, size, l.bytes.data());
            } else if (target == GL_TEXTURE_CUBE_MAP) {
                glTextureSubImage3D(name, m, 0, 0, static_cast<GLint>(face), l.width, l.height, 1, GL_RGBA,
                                    pixel_type(data.format), l.bytes.data());
            } else if (target == GL_TEXTURE_3D) {
                glTextureSubImage3D(name, m, 0, 0, 0, l.width, l.height, l.depth, GL_RGBA, pixel_type(data.format), l.bytes.data());
            } else if (target == GL_TEXTURE_1D) {
                glTextureSubImage1D(name, m, 0, l.width, GL_RGBA, pixel_type(data.format), l.bytes.data());
            } else {
                glTextureSubImage2D(name, m, 0, 0, l.width, l.height, GL_RGBA, pixel_type(data.format), l.bytes.data());
            }
        }
    if (generate && levels > 1) glGenerateTextureMipmap(name);
    glTextureParameteri(name, GL_TEXTURE_MAX_LEVEL, levels - 1);
    return texture;
}

std::vector<float> download_texture(GLuint texture, TextureType type, int face, int level, int width, int height, int depth) {
    std::vector<float> bottom_up(static_cast<size_t>(width) * height * depth * 4);
    const auto size = static_cast<GLsizei>(bottom_up.size() * sizeof(float));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (type == TextureType::Cube)
        glGetTextureSubImage(texture, level, 0, 0, face, width, height, 1, GL_RGBA, GL_FLOAT, size, bottom_up.data());
    else
        glGetTextureImage(texture, level, GL_RGBA, GL_FLOAT, size, bottom_up.data());
    if (type == TextureType::Cube) return bottom_up;  // cube faces are stored top row first
    std::vector<float> top_down(bottom_up.size());
    const size_t row = static_cast<size_t>(width) * 4;
    for (int slice = 0; slice < depth; ++slice)  // each slice flipped on its own
        for (int y = 0; y < height; ++y)
            std::copy_n(bottom_up.begin() + static_cast<ptrdiff_t>((slice * height + height - 1 - y) * row), row,
                        top_down.begin() + static_cast<ptrdiff_t>((slice * height + y) * row));
    return top_down;
}

}  // namespace fxview::gl
