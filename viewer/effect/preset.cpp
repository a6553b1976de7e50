#include "effect/preset.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

#include "effect/parser.hpp"

namespace fxview::effect {

void save_preset(const std::string& path, const Effect& effect, const std::string& technique, const ParameterValues& values) {
    nlohmann::json parameters = nlohmann::json::object();
    for (const auto& [name, numbers] : values.numbers)
        parameters[name] = numbers.size() == 1 ? nlohmann::json(numbers[0]) : nlohmann::json(numbers);
    for (const auto& [name, file] : values.textures) parameters[name] = file;
    const nlohmann::json preset = {{"effect", effect.path}, {"technique", technique}, {"parameters", parameters}};
    std::ofstream file(path);
    if (!file) throw Error(path + ": cannot write preset");
    file << preset.dump(2) << "\n";
    if (!file) throw Error(path + ": cannot write preset");
}

Preset load_preset(const std::string& path, const Effect& effect, ParameterValues& values) {
    std::ifstream file(path);
    if (!file) throw Error(path + ": cannot open preset");
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(file);
    } catch (const nlohmann::json::parse_error& error) {
        throw Error(path + ": not a valid JSON preset: " + error.what());
    }
    if (!json.is_object() || !json.contains("parameters") || !json["parameters"].is_object())
        throw Error(path + ": a preset needs a \"parameters\" object");
    Preset preset;
    preset.effect = json.value("effect", "");
    preset.technique = json.value("technique", "");
    ParameterValues updated = values;  // all or nothing: a bad entry leaves `values` untouched
    for (const auto& [name, value] : json["parameters"].items()) {
        const Parameter* parameter = effect.find_parameter(name);
        if (!parameter || !parameter->semantic.empty())
            throw Error(path + ": preset sets '" + name + "', which " + effect.path + " has no editable parameter for");
        if (is_sampler_type(parameter->type)) {
            if (!value.is_string()) throw Error(path + ": preset value of sampler " + name + " must be a file name");
            updated.textures[name] = value.get<std::string>();
            continue;
        }
        std::vector<double> numbers;
        if (value.is_number() || value.is_boolean()) numbers.push_back(value.is_boolean() ? value.get<bool>() : value.get<double>());
        else if (value.is_array())
            for (const auto& item : value) {
                if (!item.is_number()) throw Error(path + ": preset value of " + name + " holds a non-number");
                numbers.push_back(item.get<double>());
            }
        else throw Error(path + ": preset value of " + name + " must be a number or a list of numbers");
        auto& target = updated.numbers[name];
        if (numbers.size() != target.size())
            throw Error(path + ": preset gives " + std::to_string(numbers.size()) + " value(s) for " + parameter->type + " " +
                        name + ", which takes " + std::to_string(target.size()));
        target = numbers;
    }
    values = std::move(updated);
    preset.values = values;
    return preset;
}

}  // namespace fxview::effect
