#include "effect/source_map.hpp"
#include "effect/bparam_file.hpp"
#include "effect/brdf_file.hpp"

#include <cctype>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <charconv>
#include <optional>
#include <string_view>
#include <sstream>

#include "core/text.hpp"

namespace fxview::effect {

namespace fs = std::filesystem;

const char* stage_name(ShaderStage stage) {
    switch (stage) {
        case ShaderStage::Vertex: return "vertex";
        case ShaderStage::Geometry: return "geometry";
        case ShaderStage::Fragment: return "fragment";
    }
    return "?";
}

namespace {

const char* const kShaderSourceExtensions = ".glsl .glslh .glslinc .inc .vert .frag .geom .comp .tesc .tese .fx .fxh .cgfx .cg .cgh .cginc .hlsl .hlsli .h";

bool is_shader_source_name(const std::string& path) {
    const std::string extension = lower_extension(path);
    if (extension.size() < 2) return false;
    const std::string list = std::string(" ") + kShaderSourceExtensions + " ";
    return list.find(" " + extension + " ") != std::string::npos;
}

// A plain scanner instead of std::regex: regex matching recurses per character and overflows the
// stack on long lines (a line of 30 000 blanks was enough).
size_t skip_blanks(std::string_view line, size_t i) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    return i;
}

// Whether only blanks or a `//` comment follow position i.
bool only_comment_after(std::string_view line, size_t i) {
    i = skip_blanks(line, i);
    return i == line.size() || line.substr(i, 2) == "//";
}

// For a line "  #  word rest", the word and the position after it; an empty word otherwise.
std::pair<std::string_view, size_t> directive(std::string_view line) {
    size_t i = skip_blanks(line, 0);
    if (i == line.size() || line[i] != '#') return {{}, 0};
    i = skip_blanks(line, i + 1);
    const size_t word = i;
    while (i < line.size() && (std::isalnum(static_cast<unsigned char>(line[i])) || line[i] == '_')) ++i;
    return {line.substr(word, i - word), i};
}

bool is_pragma_once(std::string_view line) {
    const auto [word, after] = directive(line);
    if (word != "pragma") return false;
    const size_t i = skip_blanks(line, after);
    return i > after && line.substr(i, 4) == "once" && (i + 4 == line.size() || !std::isalnum(static_cast<unsigned char>(line[i + 4]))) &&
           only_comment_after(line, i + 4);
}

// The file name of `#include "name"` or `#include <name>`; nullopt for a malformed name.
std::optional<std::string> include_name(std::string_view rest) {
    const size_t open = skip_blanks(rest, 0);
    if (open == rest.size() || (rest[open] != '"' && rest[open] != '<')) return std::nullopt;
    const size_t close = rest.find_first_of("\">", open + 1);
    if (close == std::string_view::npos || close == open + 1 || !only_comment_after(rest, close + 1)) return std::nullopt;
    // Windows paths of legacy effects (include\\Quad.fxh): any run of backslashes is one separator.
    std::string name;
    for (const char c : rest.substr(open + 1, close - open - 1))
        if (c != '\\') name += c;
        else if (name.empty() || name.back() != '/') name += '/';
    return name;
}

constexpr size_t kMaxIncludeName = 1024;

}  // namespace

SourceMap SourceMap::load(const std::string& path, const std::vector<std::string>& include_dirs, const ResourceLimits& limits,
                          const FileAccessPolicy& access) {
    SourceMap map;
    std::vector<std::string> stack;
    if (!is_bparam_file(path)) {
        map.append_file(path, {include_dirs, limits, access}, stack, nullptr);
        return map;
    }
    // A BRDF Explorer parameter file: the .brdf it names, with its values as the defaults.
    BparamFile bparam = read_bparam_file(path, limits);
    if (!is_brdf_file(bparam.brdf)) throw EffectError({path, 1}, "'" + excerpt(bparam.brdf, 200) + "' is no .brdf file (a .bparam holds values for one)");
    // The .brdf it names is the file the user chose, as when opened itself (only a .brdf: no other file
    // can be read this way); its own includes stay under `access`.
    FileAccessPolicy with_brdf = access;
    with_brdf.allow_file(bparam.brdf);
    map.warnings_ = bparam.warnings;
    map.append_file(bparam.brdf, {include_dirs, limits, with_brdf, &bparam.values}, stack, nullptr);
    for (const auto& [name, value] : bparam.values)
        if (!value.used)
            map.warnings_.push_back(value.where.str() + ": warning: " + bparam.brdf + " has no " + value.type + " parameter '" + name + "'; ignored");
    map.files_.push_back(path);  // watched for changes too
    return map;
}

void SourceMap::append_file(const std::string& path, const LoadContext& context, std::vector<std::string>& stack,
                            const SourceLocation* included_from) {
    std::error_code error;
    const std::string canonical = fs::weakly_canonical(path, error).string();
    if (std::find(stack.begin(), stack.end(), canonical) != stack.end()) {
        std::string chain;
        for (const auto& file : stack) chain += fs::path(file).filename().string() + " -> ";
        throw EffectError(*included_from, "include cycle: " + chain + fs::path(canonical).filename().string());
    }
    if (included_from && static_cast<std::int64_t>(stack.size()) > context.limits.include_depth)
        throw EffectError(*included_from, "#include nested deeper than " + std::to_string(context.limits.include_depth) +
                                              " levels (budget include-depth; raise it with --limit include-depth=N)");
    const SourceLocation whole_file{path, 1};
    if (!fs::is_regular_file(path, error)) {
        if (included_from) throw EffectError(*included_from, "cannot open included file '" + excerpt(path, 200) + "': " + not_a_file(path));
        throw EffectError({path, 0}, "cannot open effect file: " + not_a_file(path));
    }
    const auto size = static_cast<std::int64_t>(fs::file_size(path, error));
    if (!error && static_cast<std::int64_t>(text_.size()) + size > context.limits.source_bytes)
        throw EffectError(included_from ? *included_from : whole_file,
                          "the effect with its includes exceeds the budget source-bytes = " + std::to_string(context.limits.source_bytes) +
                              " (raise it with --limit source-bytes=N)");
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        if (included_from) throw EffectError(*included_from, "cannot open included file '" + excerpt(path, 200) + "'");
        throw EffectError({path, 0}, "cannot open effect file");
    }
    std::vector<std::string> lines;
    for (std::string line; std::getline(file, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find('\0') != std::string::npos)
            throw EffectError({path, static_cast<int>(lines.size() + 1)}, "the line holds a NUL byte: this is not an effect source file");
        lines.push_back(std::move(line));
    }
    // `#pragma once` is the include guard: such a file is expanded only the first time.
    for (auto& line : lines)
        if (is_pragma_once(line)) {
            if (!once_.insert(canonical).second) return;
            line.clear();
        }
    // A BRDF Explorer file becomes effect text first, each line keeping its line in the .brdf.
    std::vector<int> origins;
    if (!included_from && is_brdf_file(path)) {
        TranslatedLines translated = translate_brdf_file(path, lines, context.overrides);
        warnings_.insert(warnings_.end(), translated.warnings.begin(), translated.warnings.end());
        lines = std::move(translated.lines);
        origins = std::move(translated.origins);
    } else {
        for (size_t i = 0; i < lines.size(); ++i) origins.push_back(static_cast<int>(i + 1));
    }
    int index = file_index(path);
    if (index < 0) {
        index = static_cast<int>(files_.size());
        files_.push_back(path);
    }
    stack.push_back(canonical);

    for (size_t i = 0; i < lines.size(); ++i) {
        std::string& line = lines[i];
        const int number = origins[i];
        const auto [word, after] = directive(line);
        if (word == "include") {
            const SourceLocation here{path, number};
            const std::string_view rest = std::string_view(line).substr(after);
            const auto name = include_name(rest);
            if (!name) throw EffectError(here, "#include needs a file name in quotes, got '" + excerpt(rest) + "'");
            if (name->size() > kMaxIncludeName || name->find('\0') != std::string::npos)
                throw EffectError(here, "#include names a file of " + std::to_string(name->size()) + " characters (at most " +
                                            std::to_string(kMaxIncludeName) + ")");
            std::string found;
            std::vector<fs::path> candidates{fs::path(path).parent_path() / *name};
            for (const auto& dir : context.include_dirs) candidates.push_back(fs::path(dir) / *name);
            for (const auto& candidate : candidates)
                if (fs::is_regular_file(candidate, error)) {
                    found = candidate.lexically_normal().string();
                    break;
                }
            if (found.empty()) {
                std::string searched;
                for (const auto& candidate : candidates) searched += (searched.empty() ? "" : ", ") + candidate.parent_path().string();
                throw EffectError(here, "included file '" + excerpt(*name, 200) + "' not found (searched " + excerpt(searched, 400) + ")");
            }
            try {
                context.access.require(found, "included file");
            } catch (const Error& refused) {
                throw EffectError(here, refused.what());
            }
            // Only shader sources: the compiler quotes the text it reads in its messages, so an include
            // of a key file or a .env below the effect's folder would print its contents.
            if (!is_shader_source_name(found))
                throw EffectError(here, "included file '" + excerpt(*name, 200) + "' is not a shader source (" + kShaderSourceExtensions + ")");
            append_file(found, context, stack, &here);
            // Keep one line for the #include itself so that every line of the file has an origin.
            line.clear();
        }
        if (text_.size() + line.size() + 1 > static_cast<size_t>(context.limits.source_bytes))
            throw EffectError({path, number}, "the effect with its includes exceeds the budget source-bytes = " +
                                                  std::to_string(context.limits.source_bytes) + " (raise it with --limit source-bytes=N)");
        line_starts_.push_back(text_.size());
        origins_.push_back({index, number});
        text_ += line;
        text_ += '\n';
    }
    stack.pop_back();
}

int SourceMap::file_index(const std::string& name) const {
    const auto found = std::find(files_.begin(), files_.end(), name);
    return found == files_.end() ? -1 : static_cast<int>(found - files_.begin());
}

size_t SourceMap::line_index(size_t offset) const {
    const auto next = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
    return next == line_starts_.begin() ? 0 : static_cast<size_t>(next - line_starts_.begin()) - 1;
}

SourceLocation SourceMap::locate_line(int line) const {
    if (origins_.empty()) return {files_.empty() ? "" : files_.front(), 0};
    const LineOrigin origin = origins_[std::min(static_cast<size_t>(std::max(line, 1) - 1), origins_.size() - 1)];
    return {files_[origin.file], origin.line};
}

void SourceMap::replace_text(std::string text) {
    text_ = std::move(text);
    line_starts_.assign(1, 0);
    for (size_t i = 0; i < text_.size(); ++i)
        if (text_[i] == '\n' && i + 1 < text_.size()) line_starts_.push_back(i + 1);
}

SourceLocation SourceMap::locate(size_t offset) const {
    if (origins_.empty()) return {files_.empty() ? "" : files_.front(), 0};
    const LineOrigin origin = origins_[std::min(line_index(offset), origins_.size() - 1)];
    return {files_[origin.file], origin.line};
}

// Drivers disagree on source-string numbers (Mesa reports 0 for errors on the first line after a
// `#line L S`), so the file goes into the line number itself: file index * kLinesPerFile + line.
constexpr long long kLinesPerFile = 1000000;

static std::string encoded_line_directive(int file, int line) {
    return "#line " + std::to_string(file * kLinesPerFile + line) + "\n";
}

std::string SourceMap::line_directive(const SourceLocation& where) const {
    const int index = file_index(where.file);
    return encoded_line_directive(index < 0 ? 0 : index, where.line);
}

std::string SourceMap::glsl(size_t begin, size_t end) const {
    std::string out;
    if (begin >= end || origins_.empty()) return out;
    const size_t first = line_index(begin), last = line_index(end - 1);
    for (size_t i = first; i <= last && i < origins_.size(); ++i) {
        if (i == first || origins_[i].file != origins_[i - 1].file || origins_[i].line != origins_[i - 1].line + 1)
            out += encoded_line_directive(origins_[i].file, origins_[i].line);
        const size_t from = std::max(begin, line_starts_[i]);
        const size_t to = std::min(end, i + 1 < line_starts_.size() ? line_starts_[i + 1] : text_.size());
        out.append(text_, from, to - from);
    }
    if (!out.empty() && out.back() != '\n') out += '\n';
    return out;
}

bool SourceMap::has_file_prefix(const std::string& line) const {
    return std::any_of(files_.begin(), files_.end(),
                       [&](const std::string& file) { return line.rfind(file + ":", 0) == 0; });
}

namespace {

// "digits" at position i: the number and the position after it.
std::optional<std::pair<long long, size_t>> read_number(std::string_view line, size_t i) {
    long long value = 0;
    const auto [end, error] = std::from_chars(line.data() + i, line.data() + line.size(), value);
    if (error != std::errc() || end == line.data() + i) return std::nullopt;
    return std::make_pair(value, static_cast<size_t>(end - line.data()));
}

// Mesa: "0:12(3): error: ..."; NVIDIA: "0(12) : error ...". The encoded line and the message.
std::optional<std::pair<long long, std::string_view>> driver_message(std::string_view line) {
    const auto source = read_number(line, 0);
    if (!source) return std::nullopt;
    size_t i = source->second;
    if (i < line.size() && line[i] == ':') {
        const auto number = read_number(line, i + 1);
        if (!number || number->second >= line.size() || line[number->second] != '(') return std::nullopt;
        const auto column = read_number(line, number->second + 1);
        if (!column || line.substr(column->second, 3) != "): ") return std::nullopt;
        return std::make_pair(number->first, line.substr(column->second + 3));
    }
    if (i < line.size() && line[i] == '(') {
        const auto number = read_number(line, i + 1);
        if (!number || line.substr(number->second, 4) != ") : ") return std::nullopt;
        return std::make_pair(number->first, line.substr(number->second + 4));
    }
    return std::nullopt;
}

// Driver messages quote source text; a hostile identifier must not make a megabyte message.
constexpr size_t kMaxLogLine = 400;

std::string clipped(std::string_view text) {
    return text.size() <= kMaxLogLine ? std::string(text) : std::string(text.substr(0, kMaxLogLine)) + "...";
}

}  // namespace

std::string SourceMap::map_compiler_log(const std::string& log) const {
    std::istringstream lines(log);
    std::string line, out;
    while (std::getline(lines, line)) {
        if (const auto message = driver_message(line)) {
            const long long encoded = message->first;
            const auto index = static_cast<size_t>(encoded / kLinesPerFile);
            const std::string file = encoded >= 0 && index < files_.size() ? files_[index] : "<generated>";
            out += file + ":" + std::to_string(encoded % kLinesPerFile) + ": " + clipped(message->second) + "\n";
        } else if (!line.empty()) {
            out += clipped(line) + "\n";
        }
    }
    return out;
}

}  // namespace fxview::effect
