#include "effect/preset.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/limits.hpp"
#include "core/text.hpp"
#include "effect/bparam_file.hpp"
#include "effect/parser.hpp"
#include "scene/light_geometry.hpp"
#include "scene/light_intensity.hpp"

namespace fxview::effect {

void save_preset(const std::string& path, const Effect& effect, const std::string& technique, const ParameterValues& values) {
    if (is_bparam_file(path)) return save_bparam_file(path, effect, values);
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

namespace {

bool is_builtin_environment(const std::string& name) {
    return name == "studio" || name == "furnace" || name == "none" || name == "sky" || name.rfind("sky:", 0) == 0;
}

// A preset's environment files, resolved from the preset's folder and checked against `access`
// like an effect's textures: a preset travels with effects and may read no more than they may.
std::string preset_environment(const std::string& value, const std::string& where, const std::filesystem::path& folder,
                               const FileAccessPolicy& access) {
    if (value.size() > kMaxEnvironmentSourceChars)
        throw Error(where + "scene \"environment\" is " + std::to_string(value.size()) + " characters long (at most " +
                    std::to_string(kMaxEnvironmentSourceChars) + ")");
    if (is_builtin_environment(value)) return value;
    std::string resolved;
    size_t start = 0;
    for (size_t i = 0; i <= value.size(); ++i) {
        if (i < value.size() && value[i] != ',') continue;
        const std::filesystem::path file = value.substr(start, i - start);
        start = i + 1;
        if (file.empty()) throw Error(where + "scene \"environment\" names an empty file");
        const std::filesystem::path path = file.is_absolute() ? file : folder / file;
        try {
            access.require(path, "environment");
        } catch (const Error& refused) {
            throw Error(where + refused.what());
        }
        resolved += (resolved.empty() ? "" : ",") + path.string();
    }
    return resolved;
}

}  // namespace

std::string PresetScene::where(const std::string& key) const {
    const auto line = lines.find(key);
    return path + ":" + std::to_string(line == lines.end() ? 1 : line->second) + ": ";
}

PresetScene load_preset_scene(const std::string& path, const ResourceLimits& limits, FileAccessPolicy access) {
    std::string text;
    const nlohmann::json json = read_preset_json(path, limits, text);
    PresetScene scene;
    scene.path = path;
    if (json.is_object() && json.contains("effect") && json["effect"].is_string()) {
        scene.effect = json["effect"].get<std::string>();
        const std::string where = line_of(path, text, "effect");
        scene.lines["effect"] = std::stoi(where.substr(path.size() + 1));
    }
    if (!json.is_object() || !json.contains("scene")) return scene;
    const nlohmann::json& s = json["scene"];
    if (!s.is_object()) throw Error(line_of(path, text, "scene") + "\"scene\" must be an object");
    const std::filesystem::path folder = std::filesystem::path(path).parent_path().empty() ? "." : std::filesystem::path(path).parent_path();
    access.allow_folder(folder);
    for (auto item = s.begin(); item != s.end(); ++item) {
        // Not a structured binding: clang before 16 cannot capture one in the lambdas below.
        const std::string key = item.key(), name = key;
        const nlohmann::json& value = item.value();
        const std::string where = line_of(path, text, name);
        scene.lines[name] = std::stoi(where.substr(path.size() + 1));
        const auto bad = [&](const char* what) { return Error(where + "scene \"" + name + "\" must be " + what); };
        // Numbers as doubles first: a float or int conversion of 1e300 or 4294967300 would not fail.
        const auto number = [&](double low, double high, const char* what) {
            if (!value.is_number() || !(value.get<double>() >= low && value.get<double>() <= high)) throw bad(what);
            return value.get<double>();
        };
        if (key == "environment") {
            if (!value.is_string()) throw bad("a string");
            scene.environment = preset_environment(value.get<std::string>(), where, folder, access);
        } else if (key == "environment_rotate") {
            scene.environment_rotate = static_cast<float>(number(-3600, 3600, "a number of degrees, -3600 to 3600"));
        } else if (key == "environment_intensity") {
            scene.environment_intensity = static_cast<float>(number(0, 1e6, "a number 0 to 1e6"));
        } else if (key == "exposure") {
            scene.exposure = static_cast<float>(number(-30, 30, "a number of EV stops, -30 to 30"));
        } else if (key == "light_radius") {
            scene.light_radius = static_cast<float>(number(0, 1e3, "a radius in world units, 0 to 1000"));
        } else if (key == "light_shape") {
            if (!value.is_string() || !scene::parse_light_shape(value.get<std::string>())) throw bad("\"sphere\", \"disc\" or \"rectangle\"");
            scene.light_shape = value.get<std::string>();
        } else if (key == "light_size") {
            if (!value.is_array() || value.size() != 2) throw bad("[width, height] in world units, each 0 to 1000");
            glm::vec2 size;
            for (size_t i = 0; i < 2; ++i) {
                const nlohmann::json& side = value[i];
                if (!side.is_number() || !(side.get<double>() >= 0 && side.get<double>() <= 1e3)) throw bad("[width, height] in world units, each 0 to 1000");
                size[static_cast<int>(i)] = static_cast<float>(side.get<double>());
            }
            scene.light_size = size;
        } else if (key == "light_intensity") {
            if (!value.is_string() || !scene::parse_light_intensity(value.get<std::string>())) throw bad("a number (0 to 1e30) with a unit: lx, lm, cd or nit (\"500lx\")");
            scene.light_intensity = value.get<std::string>();
        } else if (key == "light_spectrum") {
            if (!value.is_string() || value.get<std::string>().empty()) throw bad("a spectral-library name");
            scene.light_spectrum = value.get<std::string>();
        } else if (key == "tone_map") {
            if (!value.is_string()) throw bad("a string");
            scene.tone_map = value.get<std::string>();
        } else if (key == "samples") {
            const double samples = number(0, 32, "an integer 0-32");
            if (!value.is_number_integer()) throw bad("an integer 0-32");
            scene.samples = static_cast<int>(samples);
        } else {
            throw Error(where + "unknown scene setting \"" + excerpt(key) +
                        "\" (environment, environment_rotate, environment_intensity, exposure, tone_map, samples, light_shape, light_radius, light_size, light_spectrum, light_intensity)");
        }
    }
    return scene;
}

namespace {

// A .bparam's values over `values`, by name (a reserved one as fxview's brdf_NAME); names the effect
// lacks are warned about, as BRDF Explorer ignores them.
Preset load_bparam_preset(const std::string& path, const Effect& effect, ParameterValues& values) {
    const BparamFile bparam = read_bparam_file(path, effect.limits);
    Preset preset;
    preset.effect = bparam.brdf;
    preset.warnings = bparam.warnings;
    ParameterValues updated = values;
    for (const auto& [name, value] : bparam.values) {
        const Parameter* parameter = effect.find_parameter(name);
        if (!parameter) parameter = effect.find_parameter("brdf_" + name);
        const auto target = parameter ? updated.numbers.find(parameter->name) : updated.numbers.end();
        if (!parameter || !parameter->semantic.empty() || target == updated.numbers.end() || target->second.size() != value.numbers.size()) {
            preset.warnings.push_back(value.where.str() + ": warning: " + effect.path + " has no " + value.type + " parameter '" + name + "'; ignored");
            continue;
        }
        std::vector<double> numbers;
        for (const std::string& word : value.numbers) {
            try {
                size_t used = 0;
                numbers.push_back(std::stod(word, &used));
                if (used != word.size()) throw std::invalid_argument(word);
            } catch (const std::exception&) {
                throw Error(value.where.str() + ": '" + excerpt(word) + "' is not a number");
            }
        }
        if (const std::string problem = value_problem(*parameter, numbers); !problem.empty()) throw Error(value.where.str() + ": " + problem);
        target->second = numbers;
    }
    values = std::move(updated);
    preset.values = values;
    return preset;
}

}  // namespace

Preset load_preset(const std::string& path, const Effect& effect, ParameterValues& values) {
    if (is_bparam_file(path)) return load_bparam_preset(path, effect, values);
    std::string text;
    const nlohmann::json json = read_preset_json(path, effect.limits, text);
    // Messages name the line where the entry's key first appears.
    const auto where = [&](const std::string& key) { return line_of(path, text, key); };
    if (!json.is_object() || !json.contains("parameters") || !json["parameters"].is_object())
        throw Error(where("parameters") + "a preset needs a \"parameters\" object");
    for (const auto& [key, value] : json.items())  // docs/preset.schema.json: no other keys
        if (key != "effect" && key != "technique" && key != "parameters" && key != "scene" && key != "note" && key != "$schema")
            throw Error(where(key) + "unknown preset key \"" + excerpt(key) + "\" (effect, technique, note, parameters, scene, $schema)");
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
        auto& target = updated.numbers[name];
        if (numbers.size() != target.size())
            throw Error(where(name) + "preset gives " + std::to_string(numbers.size()) + " value(s) for " + parameter->type + " " +
                        name + ", which takes " + std::to_string(target.size()));
        if (const std::string problem = value_problem(*parameter, numbers); !problem.empty()) throw Error(where(name) + "preset value: " + problem);
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
