#include "effect/bparam_file.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/text.hpp"
#include "effect/source_map.hpp"

namespace fxview::effect {

namespace fs = std::filesystem;

bool is_bparam_file(const std::string& path) { return lower_extension(path) == ".bparam"; }

BparamFile read_bparam_file(const std::string& path, const ResourceLimits& limits) {
    std::error_code error;
    if (!fs::is_regular_file(path, error)) throw EffectError({path, 0}, "cannot open parameter file: " + not_a_file(path));
    checked_file_size(path, limits);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw EffectError({path, 0}, "cannot open parameter file");
    BparamFile out;
    out.path = path;
    const auto warn = [&](int line, const std::string& message) { out.warnings.push_back(path + ":" + std::to_string(line) + ": warning: " + message); };
    std::string section;
    int number = 0, section_start = 0;
    bool seen_kind = false;
    for (std::string raw; std::getline(file, raw);) {
        ++number;
        if (raw.find('\0') != std::string::npos) throw EffectError({path, number}, "the line holds a NUL byte: this is not a .bparam file");
        const std::string line = trim(raw);
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> w = words(line);
        if (!seen_kind) {
            seen_kind = true;
            // BRDF Explorer: the file name is what follows the first blank of the first line.
            if (w.front() != "bparam" || w.size() < 2)
                throw EffectError({path, number}, "a .bparam file starts with 'bparam FILE' (the .brdf it holds values for), got '" + excerpt(line) + "'");
            const std::string named = trim(line.substr(line.find_first_of(" \t") + 1));
            const fs::path beside = fs::path(path).parent_path() / named;
            out.brdf = fs::path(named).is_absolute() || !fs::exists(beside, error) ? named : beside.string();
            continue;
        }
        if (w.front() == "::begin" && w.size() == 2 && section.empty()) {
            section = w[1];
            section_start = number;
            if (section != "parameters") warn(number, "section '" + excerpt(section) + "' skipped (a .bparam holds parameters)");
            continue;
        }
        if (w.front() == "::end" && w.size() == 2 && w[1] == section) {
            section.clear();
            continue;
        }
        if (section != "parameters") {
            if (section.empty()) throw EffectError({path, number}, "text outside '::begin parameters' ... '::end parameters': '" + excerpt(line) + "'");
            continue;
        }
        const size_t counts = w.front() == "float" ? 5 : w.front() == "color" ? 5 : w.front() == "bool" ? 3 : 0;
        if (counts == 0) throw EffectError({path, number}, "unknown parameter type '" + excerpt(w.front()) + "' (float, color or bool)");
        if (w.size() != counts)
            throw EffectError({path, number}, "expected '" +
                                                  std::string(w.front() == "float" ? "float NAME MIN MAX VALUE" : w.front() == "color" ? "color NAME R G B" : "bool NAME 0|1") +
                                                  "', got '" + excerpt(line) + "'");
        ParameterOverride value;
        value.type = w.front();
        value.where = {path, number};
        // float: the current value is the last number (the range is the .brdf's); color: three; bool: one.
        value.numbers = w.front() == "color" ? std::vector<std::string>(w.begin() + 2, w.end()) : std::vector<std::string>{w.back()};
        if (!out.values.emplace(w[1], value).second) warn(number, "parameter '" + excerpt(w[1]) + "' given twice: the first value counts");
    }
    if (!seen_kind) throw EffectError({path, 1}, "an empty .bparam file (it starts with 'bparam FILE')");
    if (!section.empty()) throw EffectError({path, section_start}, "'::begin " + excerpt(section) + "' without '::end " + excerpt(section) + "'");
    return out;
}

namespace {

// The .brdf an effect came from: itself, or the file its .bparam names.
std::string brdf_path_of(const Effect& effect) {
    if (!is_bparam_file(effect.path)) return effect.path;
    return read_bparam_file(effect.path, effect.limits).brdf;
}

// The name BRDF Explorer knows: fxview renames a .brdf parameter whose name its shaders hold brdf_NAME.
std::string explorer_name(const Effect& effect, const std::string& name) {
    if (name.rfind("brdf_", 0) != 0) return name;
    for (const std::string& warning : effect.sources.warnings())
        if (warning.find("parameter '" + name.substr(5) + "' is called " + name) != std::string::npos) return name.substr(5);
    return name;
}

}  // namespace

void save_bparam_file(const std::string& path, const Effect& effect, const ParameterValues& values) {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out) throw Error(path + ": cannot write parameter file");
    const std::string brdf = brdf_path_of(effect);
    std::fprintf(out, "bparam %s\n\n::begin parameters\n", brdf.c_str());
    for (const Parameter& parameter : effect.parameters) {
        const auto found = values.numbers.find(parameter.name);
        // Only the .brdf's own parameters: fxview's (light, sampling) mean nothing to BRDF Explorer.
        std::error_code error;
        const bool own = parameter.where.file == brdf || fs::equivalent(parameter.where.file, brdf, error);
        if (!own || !parameter.semantic.empty() || found == values.numbers.end() || parameter.array_size > 0) continue;
        const std::vector<double>& v = found->second;
        const std::string name = explorer_name(effect, parameter.name);
        if (parameter.type == "float" && v.size() == 1)
            std::fprintf(out, "float %s %.9g %.9g %.9g\n", name.c_str(), parameter.ui.min.value_or(0.0), parameter.ui.max.value_or(1.0), v[0]);
        else if (parameter.type == "bool" && v.size() == 1) std::fprintf(out, "bool %s %d\n", name.c_str(), v[0] != 0.0 ? 1 : 0);
        else if (parameter.type == "vec3" && v.size() == 3) std::fprintf(out, "color %s %.9g %.9g %.9g\n", name.c_str(), v[0], v[1], v[2]);
    }
    std::fprintf(out, "::end parameters\n");
    const bool failed = std::ferror(out) != 0;
    if (std::fclose(out) != 0 || failed) throw Error(path + ": cannot write parameter file");
}

}  // namespace fxview::effect
