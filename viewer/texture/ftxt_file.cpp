// FTXT, the float text format of the original ShaderViewer (seed 002 ch. 4.1): the texture size,
// then one line per texel with R;G;B;A. fxview's reading of it:
//   - blank lines and lines starting with '#' are ignored;
//   - the first line is "WIDTH HEIGHT" (also "WIDTH;HEIGHT" or "WIDTHxHEIGHT"); a lone WIDTH means height 1;
//   - then WIDTH*HEIGHT texel lines, top row first, each exactly four numbers separated by ';';
//   - too little data (or too much, or a malformed line) rejects the whole file, as in the original.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "core/text.hpp"
#include "texture/texture_file.hpp"

namespace fxview::texture {
namespace {

std::vector<std::string> split_any(const std::string& text, const std::string& separators) {
    std::vector<std::string> parts;
    std::string current;
    for (char c : text) {
        if (separators.find(c) != std::string::npos) {
            parts.push_back(current);
            current.clear();
        } else if (c != ' ' && c != '\t' && c != '\r') {
            current += c;
        }
    }
    parts.push_back(current);
    return parts;
}

bool parse_float(const std::string& text, float& value) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return !text.empty() && error == std::errc() && end == text.data() + text.size();
}

}  // namespace

TextureData load_ftxt(const std::string& path, const ResourceLimits& limits) {
    const long long file_bytes = checked_file_size(path, limits);
    std::ifstream file(path);
    if (!file) throw Error(path + ": cannot open FTXT file");
    std::string line;
    int number = 0;
    long long width = 0, height = 0, texels = 0, expected = 0;
    std::vector<float> values;
    const auto where = [&]() { return path + ":" + std::to_string(number) + ": "; };
    while (std::getline(file, line)) {
        ++number;
        if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte order mark
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        if (width == 0) {
            auto parts = split_any(line, " ;x,");
            parts.erase(std::remove(parts.begin(), parts.end(), std::string()), parts.end());
            if (parts.empty() || parts.size() > 2) throw Error(where() + "FTXT must start with the size \"WIDTH HEIGHT\"");
            for (size_t i = 0; i < parts.size(); ++i) {
                long long value = 0;
                const auto [end, error] = std::from_chars(parts[i].data(), parts[i].data() + parts[i].size(), value);
                if (error != std::errc() || end != parts[i].data() + parts[i].size() || value < 1 || value > limits.texture_dimension)
                    throw Error(where() + "bad FTXT size '" + excerpt(line) + "' (each 1.." + std::to_string(limits.texture_dimension) +
                                ", budget texture-dimension)");
                (i == 0 ? width : height) = value;
            }
            if (height == 0) height = 1;
            expected = width * height;
            check_limit(limits, "texture-bytes", expected * 16, where().substr(0, where().size() - 2), "FTXT texture of");
            // Reserve only what the file can hold (a texel line has at least 7 bytes), not what it claims.
            values.reserve(static_cast<size_t>(std::min<long long>(expected, file_bytes / 7 + 1)) * 4);
            continue;
        }
        if (texels == expected)
            throw Error(where() + "more texel lines than the size " + std::to_string(width) + "x" + std::to_string(height) + " allows");
        const auto parts = split_any(line, ";");
        if (parts.size() != 4) throw Error(where() + "a texel line needs four values R;G;B;A, found " + std::to_string(parts.size()));
        for (const auto& part : parts) {
            float value = 0;
            if (!parse_float(part, value) || !std::isfinite(value)) throw Error(where() + "'" + excerpt(part) + "' is not a finite number");
            values.push_back(value);
        }
        ++texels;
    }
    if (width == 0) throw Error(path + ": empty FTXT file (no size line)");
    if (texels < expected)
        throw Error(path + ":" + std::to_string(number) + ": FTXT data ends after " + std::to_string(texels) + " of " +
                    std::to_string(expected) + " texels; the texture is discarded");
    TextureData texture;
    texture.format = PixelFormat::RGBA32F;
    texture.source = path;
    Level level{static_cast<int>(width), static_cast<int>(height), std::vector<std::uint8_t>(values.size() * 4)};
    std::memcpy(level.bytes.data(), values.data(), level.bytes.size());
    texture.faces = {{std::move(level)}};
    return texture;
}

}  // namespace fxview::texture
