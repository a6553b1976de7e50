// DirectDraw Surface files: uncompressed RGBA8 (either channel order), RGBA16F and RGBA32F (legacy
// D3DFMT codes 113/116 or a DX10 header), BC1-BC3 (DXT1/DXT3/DXT5), with mip levels and cube faces.
// Layout: "DDS ", a 124-byte header, an optional 20-byte DX10 header, then face by face, each
// face's levels from largest to smallest.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "texture/texture_file.hpp"

namespace fxview::texture {
namespace {

constexpr std::uint32_t kMipMapCount = 0x20000;  // DDSD_MIPMAPCOUNT
constexpr std::uint32_t kFourCC = 0x4;           // DDPF_FOURCC
constexpr std::uint32_t kRgb = 0x40;             // DDPF_RGB
constexpr std::uint32_t kCubeMap = 0x200;        // DDSCAPS2_CUBEMAP
constexpr std::uint32_t kAllFaces = 0xFC00;      // DDSCAPS2_CUBEMAP_POSITIVEX ... NEGATIVEZ
constexpr std::uint32_t kVolume = 0x200000;      // DDSCAPS2_VOLUME

std::uint32_t fourcc(const char (&code)[5]) {
    return static_cast<std::uint32_t>(code[0]) | static_cast<std::uint32_t>(code[1]) << 8 |
           static_cast<std::uint32_t>(code[2]) << 16 | static_cast<std::uint32_t>(code[3]) << 24;
}

std::uint32_t word(const std::vector<std::uint8_t>& bytes, size_t offset) {
    std::uint32_t value;
    std::memcpy(&value, &bytes[offset], 4);
    return value;
}

}  // namespace

TextureData load_dds(const std::string& path, const ResourceLimits& limits) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(path + ": cannot open DDS file");
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (bytes.size() < 128 || std::memcmp(bytes.data(), "DDS ", 4) != 0 || word(bytes, 4) != 124)
        throw Error(path + ": not a DDS file (bad magic or header size)");
    const std::uint32_t flags = word(bytes, 8);
    const int height = static_cast<int>(word(bytes, 12)), width = static_cast<int>(word(bytes, 16));
    const std::uint32_t mip_count = (flags & kMipMapCount) ? std::max<std::uint32_t>(1, word(bytes, 28)) : 1;
    const std::uint32_t pf_flags = word(bytes, 80), pf_fourcc = word(bytes, 84), bit_count = word(bytes, 88);
    const std::uint32_t red_mask = word(bytes, 92);
    const std::uint32_t caps2 = word(bytes, 112);
    const int depth = (caps2 & kVolume) ? static_cast<int>(std::max<std::uint32_t>(1, word(bytes, 24))) : 1;
    check_limit(limits, "texture-dimension", std::max({width, height, depth}), path, "DDS side");
    if (width < 1 || height < 1 || depth < 1)
        throw Error(path + ": implausible DDS size " + std::to_string(width) + "x" + std::to_string(height));
    // A full mip chain ends at 1x1: floor(log2(largest side)) + 1 levels. More cannot be uploaded.
    std::uint32_t max_levels = 1;
    for (int side = std::max({width, height, depth}); side > 1; side /= 2) ++max_levels;
    if (mip_count > max_levels)
        throw Error(path + ": DDS declares " + std::to_string(mip_count) + " mip levels, but a " + std::to_string(width) + "x" +
                    std::to_string(height) + (depth > 1 ? "x" + std::to_string(depth) : std::string()) + " texture has at most " +
                    std::to_string(max_levels));
    TextureData texture;
    texture.source = path;
    size_t offset = 128;
    bool swap_red_blue = false;
    int faces = (caps2 & kCubeMap) ? 6 : 1;
    if ((caps2 & kCubeMap) && (caps2 & kAllFaces) != kAllFaces)
        throw Error(path + ": DDS cube maps must hold all six faces");
    if ((pf_flags & kFourCC) && pf_fourcc == fourcc("DX10")) {
        if (bytes.size() < 148) throw Error(path + ": DDS DX10 header ends early");
        const std::uint32_t dxgi = word(bytes, 128), misc = word(bytes, 136), array_size = word(bytes, 140);
        offset = 148;
        switch (dxgi) {
            case 2: texture.format = PixelFormat::RGBA32F; break;   // R32G32B32A32_FLOAT
            case 10: texture.format = PixelFormat::RGBA16F; break;  // R16G16B16A16_FLOAT
            case 28: texture.format = PixelFormat::RGBA8; break;    // R8G8B8A8_UNORM
            case 71: texture.format = PixelFormat::BC1; break;
            case 74: texture.format = PixelFormat::BC2; break;
            case 77: texture.format = PixelFormat::BC3; break;
            default: throw Error(path + ": unsupported DXGI format " + std::to_string(dxgi) + " in DDS");
        }
        if (misc & 0x4) faces = 6;  // D3D11_RESOURCE_MISC_TEXTURECUBE
        if (array_size > 1) throw Error(path + ": DDS texture arrays are not supported");
    } else if (pf_flags & kFourCC) {
        if (pf_fourcc == fourcc("DXT1")) texture.format = PixelFormat::BC1;
        else if (pf_fourcc == fourcc("DXT3")) texture.format = PixelFormat::BC2;
        else if (pf_fourcc == fourcc("DXT5")) texture.format = PixelFormat::BC3;
        else if (pf_fourcc == 113) texture.format = PixelFormat::RGBA16F;  // D3DFMT_A16B16G16R16F
        else if (pf_fourcc == 116) texture.format = PixelFormat::RGBA32F;  // D3DFMT_A32B32G32R32F
        else throw Error(path + ": unsupported DDS FourCC 0x" + [&] {
                char hex[16];
                std::snprintf(hex, sizeof hex, "%08X", pf_fourcc);
                return std::string(hex);
            }());
    } else if ((pf_flags & kRgb) && bit_count == 32 && (red_mask == 0xFF || red_mask == 0xFF0000)) {
        texture.format = PixelFormat::RGBA8;
        swap_red_blue = red_mask == 0xFF0000;  // stored B, G, R, A
    } else {
        throw Error(path + ": unsupported DDS pixel format (flags 0x" + std::to_string(pf_flags) + ", " +
                    std::to_string(bit_count) + " bits)");
    }
    {  // the size the header claims, checked before any level is copied
        std::int64_t total = 0;
        for (int w = width, h = height, d = depth, m = 0; m < static_cast<int>(mip_count); ++m, w = std::max(1, w / 2),
                 h = std::max(1, h / 2), d = std::max(1, d / 2))
            total += static_cast<std::int64_t>(level_size(texture.format, w, h, d));
        check_limit(limits, "texture-bytes", total * faces, path, "decoded DDS of");
    }
    texture.type = faces == 6 ? TextureType::Cube : (caps2 & kVolume) ? TextureType::Tex3D : TextureType::Tex2D;
    if (faces == 6 && width != height) throw Error(path + ": DDS cube faces must be square");
    for (int face = 0; face < faces; ++face) {
        std::vector<Level> levels;
        int w = width, h = height, d = depth;
        for (std::uint32_t m = 0; m < mip_count; ++m) {
            const size_t size = level_size(texture.format, w, h, d);
            if (offset + size > bytes.size())
                throw Error(path + ": DDS data ends early (face " + std::to_string(face) + ", level " + std::to_string(m) + ")");
            Level level{w, h,
                        std::vector<std::uint8_t>(bytes.begin() + static_cast<ptrdiff_t>(offset),
                                                  bytes.begin() + static_cast<ptrdiff_t>(offset + size)),
                        d};
            if (swap_red_blue)
                for (size_t i = 0; i < level.bytes.size(); i += 4) std::swap(level.bytes[i], level.bytes[i + 2]);
            levels.push_back(std::move(level));
            offset += size;
            w = std::max(1, w / 2);
            h = std::max(1, h / 2);
            d = std::max(1, d / 2);
        }
        texture.faces.push_back(std::move(levels));
    }
    return texture;
}

}  // namespace fxview::texture
