#include "effect/brdf_file.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

#include "core/text.hpp"
#include "effect/source_map.hpp"

namespace fxview::effect {
namespace {

bool is_identifier(const std::string& name) {
    if (name.empty() || name.size() > 64 || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
    for (const char c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    return name.rfind("gl_", 0) != 0;
}

// A number as GLSL float text; throws at `where` if `word` is not one.
std::string checked_number(const std::string& word, const SourceLocation& where, const std::string& what) {
    double value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value))
        throw EffectError(where, what + ": '" + excerpt(word) + "' is not a number");
    std::ostringstream text;
    text.precision(9);
    text << value;
    std::string out = text.str();
    if (out.find_first_of(".e") == std::string::npos) out += ".0";
    return out;
}

std::string parameter_line(const std::vector<std::string>& w, const SourceLocation& where) {
    const std::string& type = w[0];
    const auto expect = [&](size_t count, const char* form) {
        if (w.size() != count) {
            std::string got;
            for (const auto& word : w) got += (got.empty() ? "" : " ") + word;
            throw EffectError(where, "expected '" + std::string(form) + "', got '" + excerpt(got) + "'");
        }
        if (!is_identifier(w[1])) throw EffectError(where, "'" + excerpt(w[1]) + "' is not a usable parameter name");
    };
    if (type == "float") {
        expect(5, "float NAME MIN MAX DEFAULT");
        const std::string low = checked_number(w[2], where, "minimum"), high = checked_number(w[3], where, "maximum"), value = checked_number(w[4], where, "default");
        if (std::stod(low) > std::stod(high)) throw EffectError(where, "the minimum " + low + " lies above the maximum " + high);
        return "uniform float " + w[1] + " < string UIName = \"" + w[1] + "\"; float UIMin = " + low + "; float UIMax = " + high +
               "; string UIGroup = \"BRDF\"; > = " + value + ";";
    }
    if (type == "color") {
        expect(5, "color NAME R G B");
        return "uniform vec3 " + w[1] + " < string UIName = \"" + w[1] + "\"; string UIWidget = \"color\"; string UIGroup = \"BRDF\"; > = {" +
               checked_number(w[2], where, "red") + ", " + checked_number(w[3], where, "green") + ", " + checked_number(w[4], where, "blue") + "};";
    }
    if (type == "bool") {
        expect(3, "bool NAME DEFAULT");
        const std::string& value = w[2];
        if (value != "0" && value != "1" && value != "true" && value != "false")
            throw EffectError(where, "a bool's default is 0, 1, true or false, not '" + excerpt(value) + "'");
        return "uniform bool " + w[1] + " < string UIName = \"" + w[1] + "\"; string UIGroup = \"BRDF\"; > = " +
               (value == "1" || value == "true" ? "true" : "false") + ";";
    }
    throw EffectError(where, "unknown parameter type '" + excerpt(type) + "' (float, color or bool)");
}

bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `line` holds `vec3 BRDF(` after a non-identifier character (a definition, not only a
// call). A plain scan, linear in the line: std::regex recursed per character and overflowed the
// stack on long lines.
bool defines_brdf_function(const std::string& line) {
    const auto blank = [&](size_t at) { return at < line.size() && std::isspace(static_cast<unsigned char>(line[at])); };
    for (size_t at = line.find("vec3"); at != std::string::npos; at = line.find("vec3", at + 1)) {
        if (at > 0 && is_identifier_char(line[at - 1])) continue;
        size_t next = at + 4;
        if (!blank(next)) continue;
        while (blank(next)) ++next;
        if (line.compare(next, 4, "BRDF") != 0) continue;
        next += 4;
        while (blank(next)) ++next;
        if (next < line.size() && line[next] == '(') return true;
    }
    return false;
}

// The parameter types of the first definition `RETURN NAME(TYPE a, TYPE b, ...)` in `text` (qualifiers
// in/const dropped), or nothing if there is none.
std::optional<std::vector<std::string>> parameter_types(const std::string& text, const std::string& return_type, const std::string& name) {
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
        if ((at > 0 && is_identifier_char(text[at - 1])) || (at + name.size() < text.size() && is_identifier_char(text[at + name.size()]))) continue;
        const std::vector<std::string> before = words(text.substr(at >= 64 ? at - 64 : 0, at >= 64 ? 64 : at));
        size_t open = at + name.size();
        while (open < text.size() && std::isspace(static_cast<unsigned char>(text[open]))) ++open;
        if (before.empty() || before.back() != return_type || open >= text.size() || text[open] != '(') continue;
        const size_t close = text.find(')', open);
        if (close == std::string::npos) return std::nullopt;
        std::vector<std::string> types;
        std::stringstream list(text.substr(open + 1, close - open - 1));
        for (std::string parameter; std::getline(list, parameter, ',');) {
            std::vector<std::string> w = words(trim(parameter));
            while (!w.empty() && (w.front() == "in" || w.front() == "const")) w.erase(w.begin());
            if (!w.empty()) types.push_back(w.front());
        }
        return types;
    }
    return std::nullopt;
}

// Whether an isFunc section defines the sampler fxview uses (docs/effect-format.md): a direction drawn
// for a given one, and the density it is drawn with.
bool defines_sampler(const std::string& section) {
    return parameter_types(section, "vec3", "sampleBRDF") == std::vector<std::string>{"vec3", "vec3", "vec3", "vec3", "vec2"} &&
           parameter_types(section, "float", "pdfBRDF") == std::vector<std::string>{"vec3", "vec3", "vec3", "vec3", "vec3"};
}

constexpr const char* kSamplerSignature = "vec3 sampleBRDF(vec3 V, vec3 N, vec3 X, vec3 Y, vec2 u) and float pdfBRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)";

// Names the programs a .brdf file is compiled into already declare at global scope (effects/lib:
// vertex inputs and outputs, the output `color`, the scene's uniforms; the environment's helpers are
// every name starting with environment_, is_reserved()). A file's own use of one is renamed
// brdf_NAME throughout its shader block, so that no user name can clash; names starting with fx_/Fx
// are fxview's (docs/effect-format.md).
const std::set<std::string>& reserved_names() {
    static const std::set<std::string> names = {
        "color", "uv", "corner", "main", "in_position", "in_normal", "in_tangent", "in_bitangent", "in_uv", "vs_out", "fs_in", "VertexData",
        "kFxEnvironmentSamples", "kFxEnvironmentDiscs", "metallic_roughness_discs", "World", "WorldInverseTranspose", "ViewProjection", "CameraPosition", "LightPosition",
        "LightIrradiance", "kPi"};
    return names;
}

bool is_reserved(const std::string& word) { return reserved_names().count(word) || word.rfind("environment_", 0) == 0; }

// `line` with every reserved identifier (as a whole word) renamed brdf_NAME.
std::string rename_reserved(const std::string& line, std::set<std::string>& renamed) {
    std::string out;
    out.reserve(line.size());
    for (size_t at = 0; at < line.size();) {
        if (!is_identifier_char(line[at]) || (at > 0 && is_identifier_char(line[at - 1]))) {
            out += line[at++];
            continue;
        }
        size_t end = at;
        while (end < line.size() && is_identifier_char(line[end])) ++end;
        const std::string word = line.substr(at, end - at);
        if (is_reserved(word) && !std::isdigit(static_cast<unsigned char>(word[0]))) {
            out += "brdf_" + word;
            renamed.insert(word);
        } else {
            out += word;
        }
        at = end;
    }
    return out;
}

}  // namespace

bool is_brdf_file(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".brdf";
}

TranslatedLines translate_brdf_file(const std::string& path, const std::vector<std::string>& lines, ParameterOverrides* overrides) {
    TranslatedLines out;
    const auto emit = [&](std::string text, int origin) {
        out.lines.push_back(std::move(text));
        out.origins.push_back(origin);
    };
    const auto warn = [&](int line, const std::string& message) { out.warnings.push_back(path + ":" + std::to_string(line) + ": warning: " + message); };
    enum class Block { None, Parameters, Shader, Skipped };
    std::string skipped;  // the name of the section being skipped
    std::set<std::string> renamed;  // reserved names the shader block used
    Block block = Block::None;
    int block_start = 0;
    bool has_shader = false, seen_kind = false, defines_brdf = false;
    // The isFunc section: compiled after the shader block (it may call its helpers) where it defines
    // the sampler fxview uses, else skipped with a warning.
    std::vector<std::pair<std::string, int>> sampler;
    int sampler_start = 0;
    bool uses_sampler = false;
    const auto end_sampler = [&] {
        std::string text;
        for (const auto& [line, number] : sampler) text += line + "\n";
        uses_sampler = defines_sampler(text);
        if (!uses_sampler) {
            warn(sampler_start, std::string("the importance-sampling section 'isFunc' does not define ") + kSamplerSignature +
                                    ", which fxview samples with; skipped (brdf-check samples with its own strategies)");
            sampler.clear();
        }
    };
    int shader_start = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        const int number = static_cast<int>(i + 1);
        const SourceLocation where{path, number};
        const std::string line = trim(lines[i]);
        if (block == Block::Skipped) {
            if (words(line) == std::vector<std::string>{"::end", skipped}) {
                block = Block::None;
                if (skipped == "isFunc") end_sampler();
            } else if (skipped == "isFunc") {
                sampler.emplace_back(lines[i], number);
            }
            emit("", number);
            continue;
        }
        if (block == Block::Shader) {
            if (line == "::end shader") {
                block = Block::None;
                emit("", number);
            } else {
                defines_brdf = defines_brdf || defines_brdf_function(lines[i]);
                emit(rename_reserved(lines[i], renamed), number);  // GLSL as written, but for names fxview's shaders hold
            }
            continue;
        }
        if (line.empty() || line[0] == '#') {
            emit("", number);
            continue;
        }
        if (!seen_kind) {
            seen_kind = true;
            // Only the first word counts (BRDF Explorer's files say `analytic` and sometimes more).
            if (words(line).front() != "analytic")
                throw EffectError(where, "a .brdf file fxview can render starts with 'analytic' (measured and image BRDFs are not supported), got '" +
                                             excerpt(line) + "'");
            // The effect's own prelude: the shared vertex stage and its uniforms.
            emit("#include \"standard.glsl\"", number);
            continue;
        }
        if (line.rfind("::", 0) == 0) {
            if (line == "::begin parameters" && block == Block::None) {
                block = Block::Parameters;
                block_start = number;
            } else if (line == "::end parameters" && block == Block::Parameters) {
                block = Block::None;
            } else if (line == "::begin shader" && block == Block::None) {
                if (has_shader) throw EffectError(where, "a second shader block");
                block = Block::Shader;
                block_start = shader_start = number;
                has_shader = true;
            } else if (const auto w = words(line); block == Block::None && w.size() == 2 && w[0] == "::begin") {
                // A section fxview does not use: skipped to its end, as BRDF Explorer skips what it does not know.
                skipped = w[1];
                block = Block::Skipped;
                block_start = number;
                if (w[1] == "isFunc") {
                    if (sampler_start) throw EffectError(where, "a second isFunc section");
                    sampler_start = number;
                } else {
                    warn(number, "unknown section '" + excerpt(w[1]) + "' skipped");
                }
            } else {
                throw EffectError(where, "unexpected '" + excerpt(line) + "'" +
                                             (block == Block::Parameters ? " inside the parameters block (it ends with '::end parameters')" : ""));
            }
            emit("", number);
            continue;
        }
        if (block != Block::Parameters) throw EffectError(where, "text outside a '::begin parameters' or '::begin shader' block: '" + excerpt(line) + "'");
        std::vector<std::string> w = words(trim(line.substr(0, line.find('#'))));  // a trailing # comment is allowed
        if (overrides && w.size() == (w[0] == "bool" ? 3u : 5u))
            if (const auto found = overrides->find(w[1]); found != overrides->end()) {
                ParameterOverride& value = found->second;
                if (value.type != w[0]) {
                    out.warnings.push_back(value.where.str() + ": warning: '" + w[1] + "' is a " + w[0] + " in " + path + ", not a " + value.type + "; its value is ignored");
                    value.used = true;  // said here; not again as missing
                } else {
                    // The value's numbers replace the default's, checked as the file's own (at the override's line).
                    const SourceLocation& at = value.where;
                    for (size_t k = 0; k < value.numbers.size(); ++k) {
                        if (w[0] != "bool") checked_number(value.numbers[k], at, w[1]);
                        w[w.size() - value.numbers.size() + k] = value.numbers[k];
                    }
                    if (w[0] == "bool" && w.back() != "0" && w.back() != "1") throw EffectError(at, "a bool's value is 0 or 1, not '" + excerpt(w.back()) + "'");
                    value.used = true;
                }
            }
        if (w.size() >= 2 && is_reserved(w[1])) {
            warn(number, "parameter '" + w[1] + "' is called brdf_" + w[1] + " in fxview (--set brdf_" + w[1] + "=...): fxview's shaders hold that name");
            w[1] = "brdf_" + w[1];
        }
        emit(parameter_line(w, where), number);
    }
    const int last = static_cast<int>(lines.size());
    if (!seen_kind) throw EffectError({path, 1}, "an empty .brdf file (it starts with 'analytic')");
    if (block == Block::Parameters) throw EffectError({path, block_start}, "'::begin parameters' without '::end parameters'");
    if (block == Block::Shader) {  // BRDF Explorer ends the shader at the end of the file
        warn(block_start, "'::begin shader' without '::end shader': the shader ends at the end of the file");
        block = Block::None;
    }
    if (block == Block::Skipped) {
        warn(block_start, "section '" + excerpt(skipped) + "' without '::end " + excerpt(skipped) + "': " +
                              (skipped == "isFunc" ? "it ends at the end of the file" : "skipped to the end of the file"));
        if (skipped == "isFunc") end_sampler();
    }
    if (!has_shader) throw EffectError({path, last}, "no '::begin shader' block defining vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)");
    if (!defines_brdf)
        throw EffectError({path, shader_start}, "the shader block does not define vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)");
    if (uses_sampler) {
        // brdf_grid.glsl calls it where FX_BRDF_IS_FUNC is defined; FxFileSampler tells brdf-check.
        emit("#define FX_BRDF_IS_FUNC 1", sampler_start);
        emit("uniform bool FxFileSampler < string UIName = \"File's own sampling (isFunc)\"; string UIGroup = \"BRDF grid\"; > = true;", sampler_start);
        for (const auto& [text, number] : sampler) emit(rename_reserved(text, renamed), number);
    }
    for (const std::string& name : renamed)
        warn(shader_start, "the shader block's '" + name + "' is renamed brdf_" + name + " (fxview's shaders hold that name)");
    // The techniques that render BRDF() (effects/lib/brdf_file.glsl), after it is defined.
    emit("#include \"brdf_file.glsl\"", last);
    return out;
}

}  // namespace fxview::effect
