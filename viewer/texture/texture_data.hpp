// Texture contents in memory, independent of GL: one or six faces, each with a chain of mip
// levels, in one pixel format. Rows of every level run top to bottom as in the source file.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace fxview::texture {

enum class PixelFormat { RGBA8, RGBA16F, RGBA32F, BC1, BC2, BC3 };
enum class TextureType { Tex1D, Tex2D, Tex3D, Cube };

struct Level {
    int width = 0, height = 0;
    std::vector<std::uint8_t> bytes;
    int depth = 1;  // slices of a 3D texture, each `height` rows, slice 0 first
};

struct TextureData {
    TextureType type = TextureType::Tex2D;
    PixelFormat format = PixelFormat::RGBA8;
    std::vector<std::vector<Level>> faces;  // faces[face][level]; cube faces in GL order +X -X +Y -Y +Z -Z
    std::string source;                     // file it came from, for messages and the texture viewer

    int width() const { return faces.empty() || faces[0].empty() ? 0 : faces[0][0].width; }
    int height() const { return faces.empty() || faces[0].empty() ? 0 : faces[0][0].height; }
    int depth() const { return faces.empty() || faces[0].empty() ? 0 : faces[0][0].depth; }
    int levels() const { return faces.empty() ? 0 : static_cast<int>(faces[0].size()); }
};

bool is_compressed(PixelFormat format);
int bytes_per_pixel(PixelFormat format);  // 0 for block-compressed formats
int bytes_per_block(PixelFormat format);  // 0 for uncompressed formats
size_t level_size(PixelFormat format, int width, int height, int depth = 1);
const char* format_name(PixelFormat format);

// One RGBA float texel of an uncompressed level (tests, the texture viewer, CPU samplers).
void read_texel(const TextureData& texture, int face, int level, int x, int y, float rgba[4], int z = 0);

// Converts an uncompressed texture to another uncompressed format (8-bit values are unorm,
// rounded to nearest; 16F rounds to nearest even). Throws Error for compressed formats.
TextureData convert(const TextureData& texture, PixelFormat target);

// Flips every level (every slice of a 3D level) upside down (GL's first row is t = 0); block-compressed data is flipped
// block row by block row, and inside each block, without decoding.
void flip_vertically(TextureData& texture);

}  // namespace fxview::texture
