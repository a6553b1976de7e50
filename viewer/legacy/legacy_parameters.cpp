#include "legacy/legacy_parameters.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <tuple>

#include "core/text.hpp"
#include "effect/parser.hpp"
#include "effect/semantics.hpp"
#include "effect/texture_annotations.hpp"

namespace fxview::legacy {
namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::string annotation_text(const LegacyGlobal& g, const char* name) {
    for (const auto& a : g.annotations)
        if (to_lower(a.name) == name && a.value.is_string) return to_lower(a.value.text);
    return {};
}

// UI hints annotation by annotation: one that does not fit (a float4 UIMin) is skipped, not fatal.
effect::UiHints tolerant_ui_hints(const std::vector<effect::Annotation>& annotations, std::vector<std::string>& warnings) {
    effect::UiHints ui;
    for (effect::Annotation a : annotations) {
        // RenderMonkey and FX Composer write per-component ranges (float4 UIMin = {-10, -10, -10, -10}):
        // the UI takes one range for all components, the first.
        const std::string key = to_lower(a.name);
        if ((key == "uimin" || key == "uimax" || key == "uistep" || key == "sasuimin" || key == "sasuimax") && !a.value.is_string &&
            a.value.numbers.size() > 1)
            a.value.numbers.resize(1);
        effect::UiHints one;
        try {
            one = effect::ui_hints_from({a});
        } catch (const effect::EffectError& error) {
            {
            const std::string text = error.what();  // "file:line: message"
            const size_t colon = text.find(": ");
            warnings.push_back(colon == std::string::npos ? text : text.substr(0, colon) + ": warning: " + text.substr(colon + 2) + " (ignored)");
        }
            continue;
        }
        if (!one.label.empty()) ui.label = one.label;
        if (!one.widget.empty()) ui.widget = one.widget;
        if (one.min) ui.min = one.min;
        if (one.max) ui.max = one.max;
        if (one.step) ui.step = one.step;
        if (!one.group.empty()) ui.group = one.group;
        if (one.order) ui.order = one.order;
        if (!one.unit.empty()) ui.unit = one.unit;
        if (!one.help.empty()) ui.help = one.help;
        if (!one.items.empty()) ui.items = one.items;
        if (!one.at_least.empty()) ui.at_least = one.at_least;
    }
    if (ui.min && ui.max && *ui.min > *ui.max) ui.max.reset();
    return ui;
}

texture::TextureType sampler_texture_type(const std::string& glsl) {
    return glsl == "samplerCube" ? texture::TextureType::Cube : glsl == "sampler3D" ? texture::TextureType::Tex3D
         : glsl == "sampler1D"   ? texture::TextureType::Tex1D
                                 : texture::TextureType::Tex2D;
}

}  // namespace

std::string glsl_type(const std::string& legacy) {
    const std::string t = to_lower(legacy);
    if (t == "sampler" || t == "sampler2d" || t == "samplerrect") return "sampler2D";
    if (t == "samplercube") return "samplerCube";
    if (t == "sampler3d") return "sampler3D";
    if (t == "sampler1d") return "sampler1D";
    if (t == "vector") return "vec4";
    if (t == "matrix") return "mat4";
    for (const auto& [base, scalar, prefix] : {std::tuple{"float", "float", ""}, {"half", "float", ""}, {"double", "float", ""},
                                                {"fixed", "float", ""}, {"int", "int", "i"}, {"uint", "uint", "u"},
                                                {"dword", "uint", "u"}, {"bool", "bool", "b"}}) {
        const std::string b = base;
        if (t.rfind(b, 0) != 0) continue;
        const std::string rest = t.substr(b.size());
        if (rest.empty() || rest == "1") return scalar;
        if (rest.size() == 1 && rest[0] >= '2' && rest[0] <= '4') return std::string(prefix) + "vec" + rest;
        if (rest.size() == 3 && rest[1] == 'x' && rest[0] == rest[2] && rest[0] >= '2' && rest[0] <= '4' && std::string(scalar) == "float")
            return "mat" + rest.substr(0, 1);
        return {};
    }
    return {};
}

std::string scene_semantic(const LegacyGlobal& g) {
    std::string s = upper(g.semantic);
    if (s.empty()) return {};
    // Spellings of the same matrices: Model for World, ...IT for InverseTranspose, ...I for Inverse.
    if (s.rfind("MODEL", 0) == 0) s = "WORLD" + s.substr(5);
    for (const auto& [from, to] : {std::pair{"WORLDVIEWPROJ", "WORLDVIEWPROJECTION"}, {"VIEWPROJ", "VIEWPROJECTION"}, {"PROJ", "PROJECTION"}})
        if (s.rfind(from, 0) == 0 && s.rfind(to, 0) != 0) s = std::string(to) + s.substr(std::string(from).size());
    for (const auto& [suffix, full] : {std::pair{"INVTRANS", "INVERSETRANSPOSE"}, {"INVERSETRANSPOSE", "INVERSETRANSPOSE"}, {"IT", "INVERSETRANSPOSE"},
                                       {"INV", "INVERSE"}, {"INVERSE", "INVERSE"}, {"I", "INVERSE"}}) {
        const std::string sfx = suffix;
        if (s.size() > sfx.size() && s.compare(s.size() - sfx.size(), sfx.size(), sfx) == 0) {
            const std::string candidate = s.substr(0, s.size() - sfx.size()) + full;
            if (effect::is_known_semantic(candidate)) { s = candidate; break; }
        }
    }
    if (s == "WORLDVIEWPROJECTIONMATRIX" || s == "WVP") s = "WORLDVIEWPROJECTION";
    if (effect::is_known_semantic(s) && s != "LIGHTPOSITION" && s != "LIGHTDIRECTION") return s;
    const std::string object = annotation_text(g, "object");
    const std::string name = to_lower(g.name);
    const bool camera = object.find("camera") != std::string::npos || (object.empty() && (name.find("eye") != std::string::npos || name.find("camera") != std::string::npos));
    if (s == "VIEWPOSITION" || s == "WORLDCAMERAPOSITION" || s == "CAMERAWORLDPOSITION") return "CAMERAPOSITION";  // RenderMonkey, others
    if (s == "POSITION" || s == "LIGHTPOSITION" || s == "EYEPOSITION" || s == "CAMERAPOSITION") return camera || s == "EYEPOSITION" || s == "CAMERAPOSITION" ? "CAMERAPOSITION" : "LIGHTPOSITION";
    if (s == "DIRECTION" || s == "LIGHTDIRECTION") return camera ? "" : "LIGHTDIRECTION";
    if (s == "TIME" || s == "ANIMATIONTIME") return "TIME";
    if (s == "VIEWPORTPIXELSIZE" || s == "VIEWPORTSIZE" || s == "RENDERTARGETDIMENSIONS") return "VIEWPORTPIXELSIZE";
    return {};
}

// The semantic a matrix without one names by its name, as the application that drove a DirectX SDK
// sample set it by name: g_mWorldViewProjection, matWorldViewProj, mWorld -> WorldViewProjection, ...
std::string semantic_from_name(const LegacyGlobal& g) {
    const std::string t = to_lower(g.type);
    if (!g.semantic.empty() || !(t.ends_with("4x4") || t.ends_with("4x3") || t.ends_with("3x4"))) return {};
    std::string name = g.name;
    for (const char* prefix : {"g_m", "g_", "m_", "mat", "g", "m"}) {
        const size_t n = std::string(prefix).size();
        // A short prefix only before a capital (mWorld, gView), not the start of a word (model, matrix).
        if (name.size() > n && name.compare(0, n, prefix) == 0 && (n > 2 || name[n] == '_' || std::isupper(static_cast<unsigned char>(name[n])))) {
            name = name.substr(n);
            break;
        }
    }
    LegacyGlobal named = g;
    named.semantic = name;
    const std::string semantic = scene_semantic(named);
    const bool matrix = semantic.find("WORLD") != std::string::npos || semantic.find("PROJECTION") != std::string::npos ||
                        (semantic.find("VIEW") != std::string::npos && semantic.find("VIEWPORT") == std::string::npos);
    return matrix ? semantic : std::string();
}

void add_parameter(effect::Effect& effect, const LegacyGlobal& g) {
    effect::Parameter p;
    p.name = g.name;
    p.where = g.where;
    p.array_size = g.array_size;
    p.annotations = g.annotations;
    p.type = glsl_type(g.type);
    const std::string lower_type = to_lower(g.type);
    // A non-square matrix (float4x3 World : WORLD, the DirectX SDK's idiom) with a scene semantic is
    // filled from the 4x4 matrix: the uniform block takes the rows and columns it has.
    if (p.type.empty() && !g.semantic.empty() && lower_type.size() >= 3 && lower_type[lower_type.size() - 2] == 'x' &&
        (lower_type.rfind("float", 0) == 0 || lower_type.rfind("half", 0) == 0) && !scene_semantic(g).empty())
        p.type = "mat4";
    if (p.type.empty() && (lower_type.rfind("texture", 0) == 0 || lower_type.rfind("samplerstate", 0) == 0 ||
                           lower_type.rfind("samplercomparisonstate", 0) == 0 || lower_type.find("buffer") != std::string::npos))
        return;  // DirectX 10 objects: only DX10 techniques (skipped) use them
    if (p.type.empty()) {
        effect.warnings.push_back(g.where.str() + ": warning: " + excerpt(g.type) + " " + g.name + " has no editable fxview type; it stays zero");
        return;
    }
    p.semantic = scene_semantic(g);
    if (const std::string named = semantic_from_name(g); !named.empty()) {
        p.semantic = named;
        effect.warnings.push_back(g.where.str() + ": warning: " + g.name + " has no semantic; fxview supplies it as " + named +
                                  " by its name (as the application this effect was written for would)");
    }
    if (!g.semantic.empty() && p.semantic.empty() && effect::component_count(p.type) == 16 && upper(g.semantic) != "NONE")
        effect.warnings.push_back(g.where.str() + ": warning: semantic " + excerpt(g.semantic) + " of " + g.name + " is not supplied by fxview; it keeps its default");
    p.ui = tolerant_ui_hints(g.annotations, effect.warnings);
    if (effect::is_sampler_type(p.type)) {
        p.sampler = g.sampler;
        p.texture = g.texture;
        const bool known = std::any_of(effect.textures.begin(), effect.textures.end(), [&](const auto& t) { return t.name == p.texture; });
        if (!known) {
            // No texture object: the sampler gets one of its own, a placeholder unless annotations name a file.
            effect::TextureResource own;
            own.name = p.texture.empty() ? g.name : p.texture;
            own.where = g.where;
            own.type = sampler_texture_type(p.type);
            effect::apply_texture_annotations(own, g.annotations);
            effect.textures.push_back(own);
            p.texture = own.name;
        }
        // The library's files name the texture object (UIName, UIHelp), not its sampler: the panel
        // and `list` show the sampler, so it takes the texture's words where it has none of its own.
        const auto texture = std::find_if(effect.textures.begin(), effect.textures.end(), [&](const auto& t) { return t.name == p.texture; });
        if (texture != effect.textures.end() && (p.ui.label.empty() || p.ui.help.empty())) {
            std::vector<std::string> said_already;  // the texture's own hints were read with the texture
            const effect::UiHints words = tolerant_ui_hints(texture->annotations, said_already);
            if (p.ui.label.empty()) p.ui.label = words.label;
            if (p.ui.help.empty()) p.ui.help = words.help;
        }
        effect.parameters.push_back(std::move(p));
        return;
    }
    const int components = effect::component_count(p.type) * std::max(1, p.array_size);
    if (g.default_value && !g.default_value->is_string) {
        std::vector<double> numbers = g.default_value->numbers;
        if (numbers.size() == 1 && components > 1 && p.array_size == 0 && p.type.rfind("mat", 0) != 0) numbers.assign(static_cast<size_t>(components), numbers[0]);
        if (numbers.size() != static_cast<size_t>(components)) {
            effect.warnings.push_back(g.where.str() + ": warning: default of " + g.name + " has " + std::to_string(numbers.size()) + " value(s), needs " +
                                      std::to_string(components) + "; missing ones are zero");
            numbers.resize(static_cast<size_t>(components), 0.0);
        }
        // The file writes matrices row by row; fxview keeps M column-major, where row-vector files
        // hold M transposed (docs/legacy-effects.md): their rows are M's columns already.
        const int n = p.type == "mat4" ? 4 : p.type == "mat3" ? 3 : p.type == "mat2" ? 2 : 0;
        if (n && !effect.row_vectors)
            for (int e = 0; e < std::max(1, p.array_size); ++e) {
                std::vector<double> m(numbers.begin() + e * n * n, numbers.begin() + (e + 1) * n * n);
                for (int r = 0; r < n; ++r)
                    for (int c = 0; c < n; ++c) numbers[static_cast<size_t>(e * n * n + c * n + r)] = m[static_cast<size_t>(r * n + c)];
            }
        if (p.type == "int" || p.type.rfind("ivec", 0) == 0)
            for (double& v : numbers) v = std::round(std::clamp(v, -2147483648.0, 2147483647.0));
        effect::Value value;
        value.numbers = numbers;
        p.default_value = value;
    }
    effect.parameters.push_back(std::move(p));
}

}  // namespace fxview::legacy
