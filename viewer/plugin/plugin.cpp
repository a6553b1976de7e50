#include "plugin/plugin.hpp"

#include "plugin/brdf_fit_plugin.hpp"
#include "plugin/film_fit_plugin.hpp"

namespace fxview::plugin {
namespace {

using Factory = std::unique_ptr<Plugin> (*)(const effect::Effect&, const effect::PluginDeclaration&, const std::vector<std::string>&);

// Every type an effect may name: compiled in, nothing loaded at run time.
const std::map<std::string, Factory>& registry() {
    static const std::map<std::string, Factory> factories = {{"brdf-fit", &create_brdf_fit}, {"film-fit", &create_film_fit}};
    return factories;
}

}  // namespace

std::vector<std::string> types() {
    std::vector<std::string> names;
    for (const auto& [name, factory] : registry()) names.push_back(name);
    return names;
}

std::unique_ptr<Plugin> create(const effect::Effect& effect, const effect::PluginDeclaration& declaration,
                               const std::vector<std::string>& texture_dirs) {
    const std::string type = declaration.text("Type");
    const auto found = registry().find(type);
    if (found == registry().end()) {
        std::string known;
        for (const std::string& name : types()) known += (known.empty() ? "" : ", ") + name;
        throw fxview::effect::EffectError(declaration.where, "plugin " + declaration.name + ": unknown Type '" + type + "' (fxview has: " + known + ")");
    }
    return found->second(effect, declaration, texture_dirs);
}

std::vector<std::unique_ptr<Plugin>> create_all(const effect::Effect& effect, const std::vector<std::string>& texture_dirs) {
    std::vector<std::unique_ptr<Plugin>> plugins;
    for (const auto& declaration : effect.plugins) plugins.push_back(create(effect, declaration, texture_dirs));
    return plugins;
}

std::vector<std::string> apply(const effect::Effect& effect, effect::ParameterValues& values, const Result& result) {
    std::vector<std::string> missing;
    for (const auto& [name, value] : result.parameters) {
        const auto current = values.numbers.find(name);
        if (!effect.find_parameter(name) || current == values.numbers.end() || current->second.size() != value.size()) {
            missing.push_back(name);
            continue;
        }
        current->second = value;
    }
    return missing;
}

}  // namespace fxview::plugin
