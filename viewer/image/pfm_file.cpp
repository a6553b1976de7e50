// Portable float map: "PF" (RGB), "Pf" (grey) and "PF4" (RGBA, an extension that keeps alpha),
// then "width height", then a scale whose sign gives the byte order (negative = little endian),
// then rows from the bottom up.
#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "image/image_file.hpp"

namespace fxview::image {
namespace {

float swap_bytes(float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, 4);
    bits = (bits >> 24) | ((bits >> 8) & 0xFF00u) | ((bits << 8) & 0xFF0000u) | (bits << 24);
    std::memcpy(&value, &bits, 4);
    return value;
}

}  // namespace

void write_pfm(const std::string& path, const FloatImage& image) {
    if (image.empty()) throw Error(path + ": empty image");
    const char* magic = image.channels == 1 ? "Pf" : image.channels == 3 ? "PF" : image.channels == 4 ? "PF4" : nullptr;
    if (!magic) throw Error(path + ": PFM needs 1, 3 or 4 channels");
    std::ofstream file(path, std::ios::binary);
    if (!file) throw Error(path + ": cannot open for writing");
    const bool little = std::endian::native == std::endian::little;
    file << magic << '\n' << image.width << ' ' << image.height << '\n' << (little ? "-1.0" : "1.0") << '\n';
    const size_t row = static_cast<size_t>(image.width) * image.channels;
    for (int y = image.height - 1; y >= 0; --y)
        file.write(reinterpret_cast<const char*>(image.pixel(0, y)), static_cast<std::streamsize>(row * sizeof(float)));
    if (!file) throw Error(path + ": write failed");
}

FloatImage read_pfm(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(path + ": cannot open");
    std::string magic;
    long long width = 0, height = 0;
    double scale = 0.0;
    file >> magic >> width >> height >> scale;
    if (!file) throw Error(path + ": not a PFM file (bad header)");
    file.get();  // the single whitespace character that ends the header
    const int channels = magic == "Pf" ? 1 : magic == "PF" ? 3 : magic == "PF4" ? 4 : 0;
    if (channels == 0) throw Error(path + ": not a PFM file (magic '" + magic + "')");
    if (width < 1 || height < 1 || width > 65536 || height > 65536 || scale == 0.0)
        throw Error(path + ": implausible PFM header " + std::to_string(width) + "x" + std::to_string(height));
    FloatImage image(static_cast<int>(width), static_cast<int>(height), channels);
    const size_t row = static_cast<size_t>(width) * channels;
    for (int y = image.height - 1; y >= 0; --y) {
        file.read(reinterpret_cast<char*>(image.pixel(0, y)), static_cast<std::streamsize>(row * sizeof(float)));
        if (file.gcount() != static_cast<std::streamsize>(row * sizeof(float)))
            throw Error(path + ": PFM data ends early (row " + std::to_string(image.height - 1 - y) + " of " +
                        std::to_string(height) + ")");
    }
    const bool file_little = scale < 0.0;
    if (file_little != (std::endian::native == std::endian::little))
        for (float& value : image.data) value = swap_bytes(value);
    return image;
}

}  // namespace fxview::image
