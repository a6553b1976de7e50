#include "plugin/plugin.hpp"

#include <algorithm>

#include "core/text.hpp"
#include "effect/parameter_values.hpp"

#include "plugin/brdf_fit_plugin.hpp"
#include "plugin/film_fit_plugin.hpp"

namespace fxview::plugin {
namespace {

using Factory = std::unique_ptr<Plugin> (*)(const effect::Effect&, const effect::PluginDeclaration&, const std::vector<std::string>&);

struct PluginType {
    Factory factory;
    std::vector<std::string> annotations;  // besides Type, UIName and UIHelp
};

// Every type an effect may name: compiled in, nothing loaded at run time.
const std::map<std::string, PluginType>& registry() {
    static const std::map<std::string, PluginType> factories = {
        {"brdf-fit", {&create_brdf_fit, {"Data", "DataFile", "Model", "Targets", "Technique", "Limit", "Solver", "Residual", "Loss"}}},
        {"film-fit",
         {&create_film_fit,
          {"Target", "Vary", "OuterIndex", "FilmIndex", "SubstrateIndex", "SubstrateKappa", "Light", "Observer", "Lower", "Upper", "Angle",
           "Technique"}}}};
    return factories;
}

// A misspelt annotation (Modle, Limt) would silently fall back to a default and change what the
// plugin does: every name must be one the type reads, and each only once.
void check_annotation_names(const effect::PluginDeclaration& declaration, const std::string& type, const PluginType& known) {
    std::vector<std::string> seen;
    for (const auto& annotation : declaration.annotations) {
        const std::string& name = annotation.name;
        const bool common = name == "Type" || name == "UIName" || name == "UIHelp";
        if (!common && std::find(known.annotations.begin(), known.annotations.end(), name) == known.annotations.end()) {
            std::string list;
            for (const auto& k : known.annotations) list += (list.empty() ? "" : ", ") + k;
            throw fxview::effect::EffectError(annotation.where, "plugin " + declaration.name + " (" + type + "): unknown annotation '" +
                                                                    excerpt(name) + "' (it reads Type, UIName, UIHelp, " + list + ")");
        }
        if (std::find(seen.begin(), seen.end(), name) != seen.end())
            throw fxview::effect::EffectError(annotation.where, "plugin " + declaration.name + ": annotation " + name + " given twice");
        seen.push_back(name);
    }
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
    check_annotation_names(declaration, type, found->second);
    return found->second.factory(effect, declaration, texture_dirs);
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
        const effect::Parameter* parameter = effect.find_parameter(name);
        if (!parameter || current == values.numbers.end() || current->second.size() != value.size()) {
            missing.push_back(name + ": the effect has no such parameter");
            continue;
        }
        if (const std::string problem = effect::value_problem(*parameter, value); !problem.empty()) {
            missing.push_back(name + ": " + problem);
            continue;
        }
        current->second = value;
    }
    return missing;
}

}  // namespace fxview::plugin
