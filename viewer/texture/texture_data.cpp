#include "texture/texture_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/gtc/packing.hpp>

#include "core/error.hpp"

namespace fxview::texture {

bool is_compressed(PixelFormat f) { return f == PixelFormat::BC1 || f == PixelFormat::BC2 || f == PixelFormat::BC3; }

int bytes_per_pixel(PixelFormat f) {
    switch (f) {
        case PixelFormat::RGBA8: return 4;
        case PixelFormat::RGBA16F: return 8;
        case PixelFormat::RGBA32F: return 16;
        default: return 0;
    }
}

int bytes_per_block(PixelFormat f) { return f == PixelFormat::BC1 ? 8 : is_compressed(f) ? 16 : 0; }

size_t level_size(PixelFormat f, int width, int height, int depth) {
    if (is_compressed(f))
        return static_cast<size_t>(std::max(1, (width + 3) / 4)) * std::max(1, (height + 3) / 4) * bytes_per_block(f) * depth;
    return static_cast<size_t>(width) * height * depth * bytes_per_pixel(f);
}

const char* format_name(PixelFormat f) {
    switch (f) {
        case PixelFormat::RGBA8: return "RGBA8";
        case PixelFormat::RGBA16F: return "RGBA16F";
        case PixelFormat::RGBA32F: return "RGBA32F";
        case PixelFormat::BC1: return "BC1";
        case PixelFormat::BC2: return "BC2";
        case PixelFormat::BC3: return "BC3";
    }
    return "?";
}

void read_texel(const TextureData& t, int face, int level, int x, int y, float rgba[4], int z) {
    const Level& l = t.faces.at(face).at(level);
    const size_t index = (static_cast<size_t>(z) * l.height + y) * l.width + x;
    switch (t.format) {
        case PixelFormat::RGBA8:
            for (int c = 0; c < 4; ++c) rgba[c] = l.bytes[index * 4 + c] / 255.0f;
            return;
        case PixelFormat::RGBA16F:
            for (int c = 0; c < 4; ++c) {
                std::uint16_t half;
                std::memcpy(&half, &l.bytes[index * 8 + c * 2], 2);
                rgba[c] = glm::unpackHalf1x16(half);
            }
            return;
        case PixelFormat::RGBA32F:
            std::memcpy(rgba, &l.bytes[index * 16], 16);
            return;
        default:
            throw Error(t.source + ": cannot read texels of block-compressed " + format_name(t.format));
    }
}

TextureData convert(const TextureData& t, PixelFormat target) {
    if (t.format == target) return t;
    if (is_compressed(t.format) || is_compressed(target))
        throw Error(t.source + ": cannot convert " + format_name(t.format) + " to " + format_name(target));
    TextureData out = t;
    out.format = target;
    for (size_t f = 0; f < t.faces.size(); ++f)
        for (size_t m = 0; m < t.faces[f].size(); ++m) {
            const Level& in = t.faces[f][m];
            Level& level = out.faces[f][m];
            level.bytes.assign(level_size(target, in.width, in.height, in.depth), 0);
            for (int y = 0; y < in.height * in.depth; ++y)  // slices are consecutive rows
                for (int x = 0; x < in.width; ++x) {
                    float rgba[4];
                    read_texel(t, static_cast<int>(f), static_cast<int>(m), x, y, rgba);
                    const size_t index = static_cast<size_t>(y) * in.width + x;
                    for (int c = 0; c < 4; ++c) {
                        if (target == PixelFormat::RGBA8)
                            level.bytes[index * 4 + c] = static_cast<std::uint8_t>(std::lround(std::clamp(rgba[c], 0.0f, 1.0f) * 255.0f));
                        else if (target == PixelFormat::RGBA16F) {
                            const std::uint16_t half = glm::packHalf1x16(rgba[c]);
                            std::memcpy(&level.bytes[index * 8 + c * 2], &half, 2);
                        } else {
                            std::memcpy(&level.bytes[index * 16 + c * 4], &rgba[c], 4);
                        }
                    }
                }
        }
    return out;
}

namespace {

// Reverses the first `rows` pixel rows inside one block (4, or fewer for levels under 4 texels
// high, whose texels occupy only the top rows of their blocks).
void flip_block(PixelFormat format, std::uint8_t* block, int rows) {
    const auto flip_colour = [rows](std::uint8_t* colour) {  // BC1: 2x16-bit endpoints, 1 index byte per row
        std::reverse(colour + 4, colour + 4 + rows);
    };
    if (format == PixelFormat::BC1) {
        flip_colour(block);
    } else if (format == PixelFormat::BC2) {  // 4 rows of 16-bit explicit alpha, then a BC1 block
        for (int r = 0; r < rows / 2; ++r) {
            std::swap(block[2 * r], block[2 * (rows - 1 - r)]);
            std::swap(block[2 * r + 1], block[2 * (rows - 1 - r) + 1]);
        }
        flip_colour(block + 8);
    } else {  // BC3: 2 alpha endpoints, 48 bits of 3-bit indices (12 bits per row), then a BC1 block
        std::uint64_t bits = 0;
        for (int i = 0; i < 6; ++i) bits |= static_cast<std::uint64_t>(block[2 + i]) << (8 * i);
        std::uint64_t flipped = bits;
        for (int row = 0; row < rows; ++row) {
            const int target = rows - 1 - row;
            flipped &= ~(std::uint64_t{0xFFF} << (12 * target));
            flipped |= ((bits >> (12 * row)) & 0xFFF) << (12 * target);
        }
        for (int i = 0; i < 6; ++i) block[2 + i] = static_cast<std::uint8_t>(flipped >> (8 * i));
        flip_colour(block + 8);
    }
}

}  // namespace

void flip_vertically(TextureData& t) {
    for (auto& face : t.faces)
        for (auto& level : face) {
            if (is_compressed(t.format)) {
                const int block = bytes_per_block(t.format);
                const int columns = std::max(1, (level.width + 3) / 4), rows = std::max(1, (level.height + 3) / 4);
                const size_t row_bytes = static_cast<size_t>(columns) * block;
                std::vector<std::uint8_t> flipped(level.bytes.size());
                for (int slice = 0; slice < level.depth; ++slice)
                    for (int r = 0; r < rows; ++r)
                        std::memcpy(&flipped[(static_cast<size_t>(slice) * rows + rows - 1 - r) * row_bytes],
                                    &level.bytes[(static_cast<size_t>(slice) * rows + r) * row_bytes], row_bytes);
                // Only whole blocks can be flipped without re-encoding: heights of 1-3 or multiples of 4.
                if (level.height > 4 && level.height % 4 != 0)
                    throw Error(t.source + ": cannot flip a " + format_name(t.format) + " level of height " +
                                std::to_string(level.height) + " (not a multiple of 4) without re-encoding");
                const int rows_in_block = std::min(4, level.height);
                for (size_t offset = 0; offset < flipped.size(); offset += block)
                    flip_block(t.format, &flipped[offset], rows_in_block);
                level.bytes = std::move(flipped);
            } else {
                const size_t row_bytes = static_cast<size_t>(level.width) * bytes_per_pixel(t.format);
                for (int slice = 0; slice < level.depth; ++slice) {
                    const auto first = level.bytes.begin() + static_cast<ptrdiff_t>(slice * level.height * row_bytes);
                    for (int y = 0; y < level.height / 2; ++y)
                        std::swap_ranges(first + static_cast<ptrdiff_t>(y * row_bytes), first + static_cast<ptrdiff_t>((y + 1) * row_bytes),
                                         first + static_cast<ptrdiff_t>((level.height - 1 - y) * row_bytes));
                }
            }
        }
}

}  // namespace fxview::texture
