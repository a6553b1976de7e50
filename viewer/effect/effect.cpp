// Effect's lookups by name (effect.hpp) and the GLSL type facts the parser and the programs share.
#include "effect/effect.hpp"

#include <map>
#include <vector>

#include "effect/parser.hpp"

namespace fxview::effect {

int component_count(const std::string& t) {
    static const std::map<std::string, int> counts = {
        {"float", 1}, {"vec2", 2},  {"vec3", 3},  {"vec4", 4},  {"int", 1},   {"ivec2", 2}, {"ivec3", 3},
        {"ivec4", 4}, {"uint", 1},  {"uvec2", 2}, {"uvec3", 3}, {"uvec4", 4}, {"bool", 1},  {"bvec2", 2},
        {"bvec3", 3}, {"bvec4", 4}, {"mat2", 4},  {"mat3", 9},  {"mat4", 16}};
    const auto found = counts.find(t);
    return found == counts.end() ? 0 : found->second;
}

bool is_sampler_type(const std::string& t) { return t.find("sampler") != std::string::npos; }

namespace {

// The first of `items` called `name`, or null.
template <typename Item>
const Item* find_named(const std::vector<Item>& items, const std::string& name) {
    for (const auto& item : items)
        if (item.name == name) return &item;
    return nullptr;
}

}  // namespace

const Parameter* Effect::find_parameter(const std::string& name) const { return find_named(parameters, name); }
const ShaderBlock* Effect::find_shader(const std::string& name) const { return find_named(shaders, name); }
const TextureResource* Effect::find_texture(const std::string& name) const { return find_named(textures, name); }
const PluginDeclaration* Effect::find_plugin(const std::string& name) const { return find_named(plugins, name); }
const Technique* Effect::find_technique(const std::string& name) const { return find_named(techniques, name); }
const Annotation* PluginDeclaration::find(const std::string& annotation) const { return find_named(annotations, annotation); }

std::string PluginDeclaration::text(const std::string& annotation) const {
    const Annotation* a = find(annotation);
    if (!a) return {};
    if (!a->value.is_string) throw EffectError(a->where, "plugin " + name + ": " + annotation + " must be a string");
    return a->value.text;
}

const Technique& Effect::default_technique() const {
    for (const auto& t : techniques)
        for (const auto& a : t.annotations)
            if (a.name == "Default" && !a.value.is_string && !a.value.numbers.empty() && a.value.numbers[0] != 0) return t;
    return techniques.front();
}

}  // namespace fxview::effect
