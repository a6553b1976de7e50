// Radiance .hdr (RGBE) files, read here rather than by stb_image: Debian's stb (2022-09) loops forever
// on a truncated run-length-encoded file (CVE-2021-42715) and accepts other truncated files silently.
// Every byte is checked against the end of the file; a short or malformed file is an Error naming it.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "texture/texture_file.hpp"

namespace fxview::texture {

TextureData load_hdr(const std::string& path, const ResourceLimits& limits) {
    checked_file_size(path, limits);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(path + ": cannot open");
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    size_t at = 0;
    const auto line = [&] {
        std::string text;
        while (at < bytes.size() && bytes[at] != '\n') text += static_cast<char>(bytes[at++]);
        if (at >= bytes.size()) throw Error(path + ": not a Radiance .hdr file (its header does not end)");
        ++at;
        return text;
    };
    const std::string magic = line();
    if (magic.rfind("#?", 0) != 0) throw Error(path + ": not a Radiance .hdr file (no #? signature)");
    for (std::string header = line(); !header.empty(); header = line())
        if (header.rfind("FORMAT=", 0) == 0 && header != "FORMAT=32-bit_rle_rgbe")
            throw Error(path + ": unsupported .hdr pixel format '" + header.substr(7) + "' (only 32-bit_rle_rgbe)");
    std::istringstream resolution(line());
    std::string y_axis, x_axis;
    long long height = 0, width = 0;
    resolution >> y_axis >> height >> x_axis >> width;
    if (y_axis != "-Y" || x_axis != "+X" || width <= 0 || height <= 0)
        throw Error(path + ": unsupported .hdr orientation or size (only \"-Y H +X W\", rows from the top)");
    if (width > limits.texture_dimension || height > limits.texture_dimension)
        throw BudgetError(path + ": " + std::to_string(width) + "x" + std::to_string(height) + " exceeds texture-dimension = " +
                          std::to_string(limits.texture_dimension));
    if (width * height * 16 > limits.texture_bytes)
        throw BudgetError(path + ": the decoded image would exceed texture-bytes = " + std::to_string(limits.texture_bytes));
    const auto next = [&] {
        if (at >= bytes.size()) throw Error(path + ": truncated .hdr file (pixel data ends early)");
        return bytes[at++];
    };
    std::vector<std::uint8_t> rgbe(static_cast<size_t>(width) * 4);
    std::vector<float> rgba(static_cast<size_t>(width * height) * 4);
    for (long long y = 0; y < height; ++y) {
        const bool run_length = width >= 8 && width < 32768 && at + 4 <= bytes.size() && bytes[at] == 2 && bytes[at + 1] == 2 &&
                                (bytes[at + 2] & 0x80) == 0;
        if (run_length) {
            const long long stated = (static_cast<long long>(bytes[at + 2]) << 8) | bytes[at + 3];
            if (stated != width) throw Error(path + ": malformed .hdr scanline " + std::to_string(y) + " (length " + std::to_string(stated) + ")");
            at += 4;
            for (int channel = 0; channel < 4; ++channel)
                for (long long x = 0; x < width;) {
                    int count = next();
                    const bool run = count > 128;
                    if (run) count -= 128;
                    if (count == 0 || x + count > width) throw Error(path + ": malformed .hdr run in scanline " + std::to_string(y));
                    const std::uint8_t value = run ? next() : 0;
                    for (int k = 0; k < count; ++k, ++x) rgbe[static_cast<size_t>(x) * 4 + channel] = run ? value : next();
                }
        } else {  // flat RGBE pixels
            for (long long x = 0; x < width; ++x)
                for (int channel = 0; channel < 4; ++channel) rgbe[static_cast<size_t>(x) * 4 + channel] = next();
        }
        for (long long x = 0; x < width; ++x) {
            const std::uint8_t* p = &rgbe[static_cast<size_t>(x) * 4];
            float* out = &rgba[static_cast<size_t>(y * width + x) * 4];
            // As Radiance's colr_color(): (m + 0.5) 2^(e - 128) / 256, the middle of the mantissa's step
            // (m 2^(e-136) alone is up to 0.4 % dark); e = 0 is black.
            const float scale = p[3] == 0 ? 0.0f : std::ldexp(1.0f, p[3] - 136);
            for (int c = 0; c < 3; ++c) out[c] = p[3] == 0 ? 0.0f : (p[c] + 0.5f) * scale;
            out[3] = 1.0f;
        }
    }
    TextureData texture;
    texture.type = TextureType::Tex2D;
    texture.format = PixelFormat::RGBA32F;
    texture.source = path;
    Level level;
    level.width = static_cast<int>(width);
    level.height = static_cast<int>(height);
    level.bytes.resize(rgba.size() * sizeof(float));
    std::memcpy(level.bytes.data(), rgba.data(), level.bytes.size());
    texture.faces = {{std::move(level)}};
    return texture;
}

}  // namespace fxview::texture
