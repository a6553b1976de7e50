#include "core/text.hpp"
#include "effect/texture_annotations.hpp"

#include <algorithm>
#include <cctype>
#include <map>

namespace fxview::effect {
namespace {

std::string text_of(const Annotation& a) {
    if (!a.value.is_string) throw EffectError(a.where, "annotation " + a.name + " needs a string");
    return a.value.text;
}

GLenum lookup(const std::map<std::string, GLenum>& table, const std::string& what, const std::string& value,
              const SourceLocation& where) {
    const auto found = table.find(to_lower(value));
    if (found != table.end()) return found->second;
    std::string names;
    for (const auto& [name, _] : table) names += (names.empty() ? "" : ", ") + name;
    throw EffectError(where, "unknown " + what + " '" + value + "' (expected one of " + names + ")");
}

const std::map<std::string, GLenum> kWraps = {{"repeat", GL_REPEAT}, {"wrap", GL_REPEAT},
                                              {"clamp", GL_CLAMP_TO_EDGE}, {"clamptoedge", GL_CLAMP_TO_EDGE},
                                              {"mirror", GL_MIRRORED_REPEAT}, {"mirroredrepeat", GL_MIRRORED_REPEAT}};
const std::map<std::string, GLenum> kMinFilters = {
    {"nearest", GL_NEAREST},
    {"point", GL_NEAREST},
    {"linear", GL_LINEAR},
    {"mipmap", GL_LINEAR_MIPMAP_LINEAR},
    {"linearmipmaplinear", GL_LINEAR_MIPMAP_LINEAR},
    {"linearmipmapnearest", GL_LINEAR_MIPMAP_NEAREST},
    {"nearestmipmapnearest", GL_NEAREST_MIPMAP_NEAREST},
    {"nearestmipmaplinear", GL_NEAREST_MIPMAP_LINEAR}};
const std::map<std::string, GLenum> kMagFilters = {{"nearest", GL_NEAREST}, {"point", GL_NEAREST}, {"linear", GL_LINEAR}};

void set_filter(SamplerState& s, const std::string& value, const SourceLocation& where) {
    s.min_filter = lookup(kMinFilters, "filter", value, where);
    s.mag_filter = s.min_filter == GL_NEAREST ? GL_NEAREST : GL_LINEAR;
}

}  // namespace

bool apply_texture_annotations(TextureResource& t, const std::vector<Annotation>& annotations) {
    bool any = false;
    for (const auto& a : annotations) {
        const std::string key = to_lower(a.name);
        if (key == "resourcename") {
            std::string names = text_of(a);
            t.files.clear();
            size_t start = 0;
            for (size_t i = 0; i <= names.size(); ++i)
                if (i == names.size() || names[i] == ';') {
                    std::string file = names.substr(start, i - start);
                    file.erase(0, file.find_first_not_of(' '));
                    file.erase(file.find_last_not_of(' ') + 1);
                    if (!file.empty()) t.files.push_back(file);
                    start = i + 1;
                }
            if (t.files.empty()) throw EffectError(a.where, "ResourceName is empty");
            any = true;
        } else if (key == "resourcetype") {
            const std::string type = to_lower(text_of(a));
            if (type == "1d") t.type = texture::TextureType::Tex1D;
            else if (type == "2d") t.type = texture::TextureType::Tex2D;
            else if (type == "cube") t.type = texture::TextureType::Cube;
            else if (type == "3d") t.type = texture::TextureType::Tex3D;
            else throw EffectError(a.where, "unknown ResourceType '" + text_of(a) + "' (expected 1D, 2D, 3D or CUBE)");
            any = true;
        } else if (key == "format") {
            const std::string format = to_lower(text_of(a));
            if (format == "8" || format == "rgba8" || format == "a8r8g8b8" || format == "x8r8g8b8") t.storage = TextureStorage::Unorm8;
            else if (format == "16f" || format == "rgba16f" || format == "a16b16g16r16f") t.storage = TextureStorage::Float16;
            else if (format == "32f" || format == "rgba32f" || format == "a32b32g32r32f") t.storage = TextureStorage::Float32;
            else throw EffectError(a.where, "unknown texture Format '" + text_of(a) + "' (expected 8, 16F or 32F)");
            any = true;
        } else if (key == "colorspace") {
            const std::string space = to_lower(text_of(a));
            if (space != "srgb" && space != "linear")
                throw EffectError(a.where, "unknown ColorSpace '" + text_of(a) + "' (expected sRGB or linear)");
            t.srgb = space == "srgb";
            any = true;
        } else if (key == "viewportratio") {
            const auto& n = a.value.numbers;
            if (a.value.is_string || (n.size() != 1 && n.size() != 2) || n[0] <= 0 || n.back() <= 0)
                throw EffectError(a.where, "ViewportRatio needs one or two positive numbers");
            t.viewport_ratio = {static_cast<float>(n[0]), static_cast<float>(n.back())};
            any = true;
        } else if (key == "depth") {
            const auto& n = a.value.numbers;
            if (a.value.is_string || n.size() != 1 || n[0] < 1 || n[0] > 2048)
                throw EffectError(a.where, "Depth needs a slice count in 1..2048");
            t.depth = static_cast<int>(n[0]);
            any = true;
        } else if (key == "dimensions") {
            const auto& n = a.value.numbers;
            if (a.value.is_string || n.size() != 2 || n[0] < 1 || n[1] < 1 || n[0] > 16384 || n[1] > 16384)
                throw EffectError(a.where, "Dimensions needs two sizes in 1..16384");
            t.dimensions = glm::ivec2(static_cast<int>(n[0]), static_cast<int>(n[1]));
            any = true;
        }
    }
    return any;
}

void apply_sampler_annotations(SamplerState& s, const std::vector<Annotation>& annotations) {
    for (const auto& a : annotations) {
        const std::string key = to_lower(a.name);
        if (key == "filter") set_filter(s, text_of(a), a.where);
        else if (key == "wrap") s.wrap_s = s.wrap_t = s.wrap_r = lookup(kWraps, "wrap mode", text_of(a), a.where);
        else if (key == "minfilter" || key == "magfilter" || key == "wraps" || key == "wrapt" || key == "wrapr")
            set_sampler_state(s, a.name, text_of(a), a.where);
    }
}

void set_sampler_state(SamplerState& s, const std::string& name, const std::string& value, const SourceLocation& where) {
    const std::string key = to_lower(name);
    if (key == "minfilter") s.min_filter = lookup(kMinFilters, "MinFilter", value, where);
    else if (key == "magfilter") s.mag_filter = lookup(kMagFilters, "MagFilter", value, where);
    else if (key == "filter") set_filter(s, value, where);
    else if (key == "wraps" || key == "addressu") s.wrap_s = lookup(kWraps, "wrap mode", value, where);
    else if (key == "wrapt" || key == "addressv") s.wrap_t = lookup(kWraps, "wrap mode", value, where);
    else if (key == "wrapr" || key == "addressw") s.wrap_r = lookup(kWraps, "wrap mode", value, where);
    else if (key == "wrap") s.wrap_s = s.wrap_t = s.wrap_r = lookup(kWraps, "wrap mode", value, where);
    else throw EffectError(where, "unknown sampler state '" + name + "'");
}

}  // namespace fxview::effect
