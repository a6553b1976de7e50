#include "effect/preset.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include "core/limits.hpp"
#include "core/text.hpp"
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

namespace {

nlohmann::json read_preset_json(const std::string& path, const ResourceLimits& limits, std::string& text) {
    checked_file_size(path, limits);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(path + ": cannot open preset");
    text.assign((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& error) {
        // "file:line: message" from the byte offset, without the library's own prefix and excerpt.
        const size_t offset = std::min(error.byte == 0 ? size_t{0} : error.byte - 1, text.size());
        const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n');
        throw Error(path + ":" + std::to_string(line) + ": not a valid JSON preset (syntax error at byte " + std::to_string(error.byte) + ")");
    } catch (const nlohmann::json::exception&) {
        throw Error(path + ":1: not a valid JSON preset");
    }
}

std::string line_of(const std::string& path, const std::string& text, const std::string& key) {
    const size_t at = text.find("\"" + key + "\"");
    const auto line = at == std::string::npos ? 1 : 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    return path + ":" + std::to_string(line) + ": ";
}

}  // namespace

PresetScene load_preset_scene(const std::string& path, const ResourceLimits& limits) {
    std::string text;
    const nlohmann::json json = read_preset_json(path, limits, text);
    PresetScene scene;
    if (!json.is_object() || !json.contains("scene")) return scene;
    const nlohmann::json& s = json["scene"];
    if (!s.is_object()) throw Error(line_of(path, text, "scene") + "\"scene\" must be an object");
    for (const auto& [key, value] : s.items()) {
        const std::string name = key;  // a structured binding cannot be captured before C++20's clang 16
        const auto bad = [&](const char* what) { return Error(line_of(path, text, name) + "scene \"" + name + "\" must be " + what); };
        if (key == "environment") {
            if (!value.is_string()) throw bad("a string");
            scene.environment = value.get<std::string>();
        } else if (key == "environment_rotate" || key == "environment_intensity" || key == "exposure") {
            if (!value.is_number()) throw bad("a number");
            (key == "environment_rotate" ? scene.environment_rotate : key == "exposure" ? scene.exposure : scene.environment_intensity) = value.get<float>();
        } else if (key == "tone_map") {
            if (!value.is_string()) throw bad("a string");
            scene.tone_map = value.get<std::string>();
        } else if (key == "samples") {
            if (!value.is_number_integer() || value.get<int>() < 0 || value.get<int>() > 32) throw bad("an integer 0-32");
            scene.samples = value.get<int>();
        } else {
            throw Error(line_of(path, text, key) + "unknown scene setting \"" + key +
                        "\" (environment, environment_rotate, environment_intensity, exposure, tone_map, samples)");
        }
    }
    return scene;
}

Preset load_preset(const std::string& path, const Effect& effect, ParameterValues& values) {
    std::string text;
    const nlohmann::json json = read_preset_json(path, effect.limits, text);
    // Messages name the line where the entry's key first appears.
    const auto where = [&](const std::string& key) { return line_of(path, text, key); };
    if (!json.is_object() || !json.contains("parameters") || !json["parameters"].is_object())
        throw Error(where("parameters") + "a preset needs a \"parameters\" object");
    if (json.contains("effect") && !json["effect"].is_string()) throw Error(where("effect") + "\"effect\" must be a string");
    if (json.contains("technique") && !json["technique"].is_string()) throw Error(where("technique") + "\"technique\" must be a string");
    Preset preset;
    preset.effect = json.value("effect", "");
    preset.technique = json.value("technique", "");
    ParameterValues updated = values;  // all or nothing: a bad entry leaves `values` untouched
    for (const auto& [name, value] : json["parameters"].items()) {
        const Parameter* parameter = effect.find_parameter(name);
        if (!parameter || !parameter->semantic.empty())
            throw Error(where(name) + "preset sets '" + excerpt(name) + "', which " + effect.path + " has no editable parameter for");
        if (is_sampler_type(parameter->type)) {
            if (!value.is_string()) throw Error(where(name) + "preset value of sampler " + name + " must be a file name");
            updated.textures[name] = value.get<std::string>();
            continue;
        }
        std::vector<double> numbers;
        if (value.is_number() || value.is_boolean()) numbers.push_back(value.is_boolean() ? value.get<bool>() : value.get<double>());
        else if (value.is_array())
            for (const auto& item : value) {
                if (!item.is_number()) throw Error(where(name) + "preset value of " + name + " holds a non-number");
                numbers.push_back(item.get<double>());
            }
        else throw Error(where(name) + "preset value of " + name + " must be a number or a list of numbers");
        for (double number : numbers)
            if (!std::isfinite(number)) throw Error(where(name) + "preset value of " + name + " is not a finite number");
        auto& target = updated.numbers[name];
        if (numbers.size() != target.size())
            throw Error(where(name) + "preset gives " + std::to_string(numbers.size()) + " value(s) for " + parameter->type + " " +
                        name + ", which takes " + std::to_string(target.size()));
        target = numbers;
    }
    try {
        check_constraints(effect, updated);
    } catch (const UsageError& error) {
        throw Error(path + ":1: " + error.what());
    }
    values = std::move(updated);
    preset.values = values;
    return preset;
}

}  // namespace fxview::effect
