#include "core/text.hpp"
#include "texture/texture_file.hpp"

#include <stb/stb_image.h>
#include <tinyexr.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>
#include <memory>

#include "core/error.hpp"
#include "core/limits.hpp"

namespace fxview::texture {
namespace {

TextureData single_level(const std::string& path, PixelFormat format, int width, int height, const void* data) {
    TextureData texture;
    texture.format = format;
    texture.source = path;
    Level level{width, height, {}};
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    level.bytes.assign(bytes, bytes + level_size(format, width, height));
    texture.faces = {{std::move(level)}};
    return texture;
}

}  // namespace

// Checked from the file's header before anything is decoded: a small file may claim a huge image.
static void check_image_size(const std::string& path, std::int64_t width, std::int64_t height, std::int64_t bytes_per_pixel,
                      const ResourceLimits& limits) {
    if (width < 1 || height < 1) throw Error(path + ": image has no pixels (" + std::to_string(width) + "x" + std::to_string(height) + ")");
    check_limit(limits, "texture-dimension", std::max(width, height), path, "image side");
    check_limit(limits, "texture-bytes", width * height * bytes_per_pixel, path, "decoded image of");
}

// stb_image trusts a PNG chunk's length and reserves it before reading (a 70-byte file asked for
// 1.2 GB). Every chunk must fit in the file; then nothing stb reserves exceeds the file's size.
static void check_png_chunks(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 8 || !std::equal(signature, signature + 8, bytes.begin())) return;
    for (size_t offset = 8; offset + 12 <= bytes.size();) {
        const std::uint64_t length = std::uint64_t{bytes[offset]} << 24 | std::uint64_t{bytes[offset + 1]} << 16 |
                                     std::uint64_t{bytes[offset + 2]} << 8 | bytes[offset + 3];
        if (offset + 12 + length > bytes.size())
            throw Error(path + ": PNG chunk at byte " + std::to_string(offset) + " claims " + std::to_string(length) +
                        " bytes, more than the file holds");
        if (std::equal(bytes.begin() + static_cast<std::ptrdiff_t>(offset + 4), bytes.begin() + static_cast<std::ptrdiff_t>(offset + 8), "IEND"))
            return;
        offset += 12 + length;
    }
}

TextureData load_stb_image(const std::string& path, const ResourceLimits& limits) {
    if (lower_extension(path) == ".hdr") return load_hdr(path, limits);  // never stb's HDR decoder (hdr_file.cpp)
    checked_file_size(path, limits);
    std::ifstream file(path, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max())) throw Error(path + ": image file too large");
    // stb would decode a Radiance file whatever its name, with the decoder hdr_file.cpp replaces.
    if (bytes.size() >= 2 && bytes[0] == '#' && bytes[1] == '?') return load_hdr(path, limits);
    check_png_chunks(path, bytes);
    const auto* data = bytes.data();
    const int size = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, size, &width, &height, &channels)) throw Error(path + ": cannot read image: " + stbi_failure_reason());
    check_image_size(path, width, height, 4, limits);
    std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels(stbi_load_from_memory(data, size, &width, &height, &channels, 4),
                                                                &stbi_image_free);
    if (!pixels) throw Error(path + ": cannot read image: " + stbi_failure_reason());
    return single_level(path, PixelFormat::RGBA8, width, height, pixels.get());
}

TextureData load_exr_texture(const std::string& path, const ResourceLimits& limits) {
    EXRVersion version;
    EXRHeader header;
    InitEXRHeader(&header);
    const char* error = nullptr;
    const auto fail = [&](const char* what) {
        const std::string message = error ? error : "unknown error";
        if (error) FreeEXRErrorMessage(error);
        throw Error(path + ": " + what + ": " + message);
    };
    if (ParseEXRVersionFromFile(&version, path.c_str()) != TINYEXR_SUCCESS) fail("not an OpenEXR file");
    if (ParseEXRHeaderFromFile(&header, &version, path.c_str(), &error) != TINYEXR_SUCCESS) {
        FreeEXRHeader(&header);  // a header that failed half-way still owns what it read
        fail("cannot read EXR header");
    }
    const std::int64_t width = static_cast<std::int64_t>(header.data_window.max_x) - header.data_window.min_x + 1;
    const std::int64_t height = static_cast<std::int64_t>(header.data_window.max_y) - header.data_window.min_y + 1;
    FreeEXRHeader(&header);
    check_image_size(path, width, height, 16, limits);
    float* rgba = nullptr;
    int decoded_width = 0, decoded_height = 0;
    if (LoadEXR(&rgba, &decoded_width, &decoded_height, path.c_str(), &error) != TINYEXR_SUCCESS) fail("cannot read EXR");
    std::unique_ptr<float, decltype(&std::free)> owner(rgba, &std::free);
    return single_level(path, PixelFormat::RGBA32F, decoded_width, decoded_height, rgba);
}

TextureData load_texture_file(const std::string& path, const ResourceLimits& limits) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) throw Error(path + ": " + not_a_file(path) + " (a texture file was expected)");
    checked_file_size(path, limits);
    const std::string extension = lower_extension(path);
    if (extension == ".dds") return load_dds(path, limits);
    if (extension == ".ftxt") return load_ftxt(path, limits);
    if (extension == ".exr") return load_exr_texture(path, limits);
    if (extension == ".hdr") return load_hdr(path, limits);
    for (const char* known : {".png", ".jpg", ".jpeg", ".bmp", ".tga"})
        if (extension == known) return load_stb_image(path, limits);
    throw Error(path + ": unsupported texture type '" + excerpt(extension) +
                "' (expected .png, .jpg, .bmp, .tga, .hdr, .exr, .dds or .ftxt)");
}

TextureData as_1d(const TextureData& image) {
    if (image.height() != 1)
        throw Error(image.source + ": a 1D texture needs an image one pixel high, this one is " +
                    std::to_string(image.height()));
    TextureData texture = image;
    texture.type = TextureType::Tex1D;
    return texture;
}

TextureData as_3d(const TextureData& image, int depth) {
    if (image.type != TextureType::Tex2D || image.faces.size() != 1 || image.levels() != 1)
        throw Error(image.source + ": a 3D texture is made from one plain 2D image of stacked slices");
    if (depth < 1 || image.height() % depth != 0)
        throw Error(image.source + ": height " + std::to_string(image.height()) + " does not split into " +
                    std::to_string(depth) + " equal slices");
    if (is_compressed(image.format) && (image.height() / depth) % 4 != 0)
        throw Error(image.source + ": compressed slices must be a multiple of 4 rows high");
    TextureData volume = image;
    volume.type = TextureType::Tex3D;
    volume.faces[0][0].height = image.height() / depth;
    volume.faces[0][0].depth = depth;
    return volume;
}

TextureData split_cube_cross(const TextureData& cross) {
    if (is_compressed(cross.format) || cross.faces.size() != 1)
        throw Error(cross.source + ": a cube cross must be one uncompressed image");
    const int width = cross.width(), height = cross.height();
    const bool vertical = height > width;
    const int columns = vertical ? 3 : 4, rows = vertical ? 4 : 3;
    const int size = width / columns;
    if (size == 0 || width != size * columns || height != size * rows)
        throw Error(cross.source + ": a " + std::string(vertical ? "vertical" : "horizontal") + " cube cross must be " +
                    std::to_string(columns) + "x" + std::to_string(rows) + " equal squares, the image is " +
                    std::to_string(width) + "x" + std::to_string(height));
    struct Cell {
        int column, row;
        bool rotated;  // stored upside down (the -Z face of a vertical cross)
    };
    // GL face order +X -X +Y -Y +Z -Z.
    const Cell vertical_cells[6] = {{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {1, 3, true}};
    const Cell horizontal_cells[6] = {{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {3, 1, false}};
    const int pixel = bytes_per_pixel(cross.format);
    const Level& source = cross.faces[0][0];
    TextureData cube;
    cube.type = TextureType::Cube;
    cube.format = cross.format;
    cube.source = cross.source;
    for (const Cell& cell : vertical ? vertical_cells : horizontal_cells) {
        Level face{size, size, std::vector<std::uint8_t>(level_size(cross.format, size, size))};
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const int sx = cell.rotated ? size - 1 - x : x, sy = cell.rotated ? size - 1 - y : y;
                const size_t from = (static_cast<size_t>(cell.row * size + sy) * width + cell.column * size + sx) * pixel;
                std::memcpy(&face.bytes[(static_cast<size_t>(y) * size + x) * pixel], &source.bytes[from], pixel);
            }
        cube.faces.push_back({std::move(face)});
    }
    return cube;
}

}  // namespace fxview::texture
