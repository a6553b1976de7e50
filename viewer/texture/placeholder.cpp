#include "texture/placeholder.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>

namespace fxview::texture {
namespace {

bool has(const std::string& name, const char* word) {
    std::string lower = name;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return lower.find(word) != std::string::npos;
}

// `word` starting a word of `name`: at its start, after a non-letter or as a capital (camelCase), so
// that "nmap" is found in nmapTex, bump_nmap and objectNMap but not in XToonMap.
bool has_word(const std::string& name, const char* word) {
    std::string lower = name;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (size_t at = lower.find(word); at != std::string::npos; at = lower.find(word, at + 1))
        if (at == 0 || !std::isalpha(static_cast<unsigned char>(name[at - 1])) || std::isupper(static_cast<unsigned char>(name[at]))) return true;
    return false;
}

Level level(int width, int height, int depth) {
    Level l;
    l.width = width;
    l.height = height;
    l.depth = depth;
    l.bytes.assign(static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(depth) * 4, 255);
    return l;
}

void put(Level& l, int x, int y, int z, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    const size_t i = ((static_cast<size_t>(z) * static_cast<size_t>(l.height) + static_cast<size_t>(y)) * static_cast<size_t>(l.width) + static_cast<size_t>(x)) * 4;
    l.bytes[i] = r;
    l.bytes[i + 1] = g;
    l.bytes[i + 2] = b;
}

bool is_rgbe_file(const std::string& file) {
    std::string lower = file;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return lower.ends_with(".hdr") || lower.ends_with(".rgbe");
}

}  // namespace

std::string placeholder_kind(TextureType type, const std::string& name, const std::string& file) {
    if (is_rgbe_file(file)) return std::string(type == TextureType::Cube ? "grey cube" : "grey checker") + " (RGBE-encoded)";
    if (type == TextureType::Cube) return "grey cube";
    if (type == TextureType::Tex3D) return "3D noise";
    if (type == TextureType::Tex1D) return "grey ramp";
    if (has(name, "norm") || has(name, "bump") || has_word(name, "nmap")) return "flat normal map";
    return "grey checker";
}

namespace {

TextureData placeholder_by_name(TextureType type, const std::string& name) {
    TextureData data;
    data.type = type;
    data.format = PixelFormat::RGBA8;
    data.source = "placeholder (" + placeholder_kind(type, name) + ")";
    const std::string kind = placeholder_kind(type, name);
    if (type == TextureType::Cube) {
        for (int face = 0; face < 6; ++face) {
            Level l = level(16, 16, 1);
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) put(l, x, y, 0, 128, 128, 128);
            data.faces.push_back({l});
        }
        return data;
    }
    if (type == TextureType::Tex3D) {
        Level l = level(16, 16, 16);
        std::uint32_t state = 12345;  // a fixed sequence: the same noise every run
        for (int z = 0; z < 16; ++z)
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) {
                    state = state * 1664525u + 1013904223u;
                    const auto v = static_cast<std::uint8_t>(state >> 24);
                    put(l, x, y, z, v, v, v);
                }
        data.faces.push_back({l});
        return data;
    }
    if (type == TextureType::Tex1D) {
        Level l = level(64, 1, 1);
        for (int x = 0; x < 64; ++x) put(l, x, 0, 0, static_cast<std::uint8_t>(x * 4), static_cast<std::uint8_t>(x * 4), static_cast<std::uint8_t>(x * 4));
        data.faces.push_back({l});
        return data;
    }
    Level l = level(64, 64, 1);
    const bool normal = kind == "flat normal map";
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            if (normal) {
                put(l, x, y, 0, 128, 128, 255);
            } else {
                const std::uint8_t v = ((x / 8 + y / 8) % 2) ? 200 : 120;
                put(l, x, y, 0, v, v, v);
            }
        }
    data.faces.push_back({l});
    return data;
}

}  // namespace

TextureData placeholder_texture(TextureType type, const std::string& name, const std::string& file) {
    TextureData data = placeholder_by_name(type, is_rgbe_file(file) ? std::string() : name);
    if (!is_rgbe_file(file)) return data;
    for (auto& face : data.faces)
        for (Level& l : face)
            for (size_t i = 3; i < l.bytes.size(); i += 4) l.bytes[i] = 128;
    data.source = "placeholder (" + placeholder_kind(type, name, file) + ")";
    return data;
}

}  // namespace fxview::texture
