#include "effect/source_map.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

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

SourceMap SourceMap::load(const std::string& path, const std::vector<std::string>& include_dirs) {
    SourceMap map;
    std::vector<std::string> stack;
    map.append_file(path, include_dirs, stack, nullptr);
    return map;
}

void SourceMap::append_file(const std::string& path, const std::vector<std::string>& include_dirs,
                            std::vector<std::string>& stack, const SourceLocation* included_from) {
    std::error_code error;
    const std::string canonical = fs::weakly_canonical(path, error).string();
    if (std::find(stack.begin(), stack.end(), canonical) != stack.end()) {
        std::string chain;
        for (const auto& file : stack) chain += fs::path(file).filename().string() + " -> ";
        throw EffectError(*included_from, "include cycle: " + chain + fs::path(canonical).filename().string());
    }
    std::ifstream file(path, std::ios::binary);
    if (!file || fs::is_directory(path)) {
        if (included_from) throw EffectError(*included_from, "cannot open included file '" + path + "'");
        throw EffectError({path, 0}, "cannot open effect file");
    }
    std::vector<std::string> lines;
    for (std::string line; std::getline(file, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    // `#pragma once` is the include guard: such a file is expanded only the first time.
    static const std::regex pragma_once(R"(^\s*#\s*pragma\s+once\s*(//.*)?$)");
    for (auto& line : lines)
        if (std::regex_match(line, pragma_once)) {
            if (!once_.insert(canonical).second) return;
            line.clear();
        }
    int index = file_index(path);
    if (index < 0) {
        index = static_cast<int>(files_.size());
        files_.push_back(path);
    }
    stack.push_back(canonical);

    static const std::regex include_line(R"(^\s*#\s*include\b(.*)$)");
    static const std::regex include_name(R"(^\s*[\"<]([^\">]+)[\">]\s*(//.*)?$)");
    int number = 0;
    for (std::string& line : lines) {
        ++number;
        std::smatch match;
        if (std::regex_match(line, match, include_line)) {
            const SourceLocation here{path, number};
            std::smatch name;
            const std::string rest = match[1].str();
            if (!std::regex_match(rest, name, include_name))
                throw EffectError(here, "#include needs a file name in quotes, got '" + rest + "'");
            std::string found;
            std::vector<fs::path> candidates{fs::path(path).parent_path() / name[1].str()};
            for (const auto& dir : include_dirs) candidates.push_back(fs::path(dir) / name[1].str());
            for (const auto& candidate : candidates)
                if (fs::is_regular_file(candidate)) {
                    found = candidate.lexically_normal().string();
                    break;
                }
            if (found.empty()) {
                std::string searched;
                for (const auto& candidate : candidates) searched += (searched.empty() ? "" : ", ") + candidate.parent_path().string();
                throw EffectError(here, "included file '" + name[1].str() + "' not found (searched " + searched + ")");
            }
            append_file(found, include_dirs, stack, &here);
            // Keep one line for the #include itself so that every line of the file has an origin.
            line.clear();
        }
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

std::string SourceMap::map_compiler_log(const std::string& log) const {
    static const std::regex mesa(R"(^(\d+):(\d+)\(\d+\): (.*)$)");
    static const std::regex nvidia(R"(^(\d+)\((\d+)\) : (.*)$)");
    std::istringstream lines(log);
    std::string line, out;
    while (std::getline(lines, line)) {
        std::smatch match;
        if (std::regex_match(line, match, mesa) || std::regex_match(line, match, nvidia)) {
            const long long encoded = std::stoll(match[2].str());
            const auto index = static_cast<size_t>(encoded / kLinesPerFile);
            const std::string file = index < files_.size() ? files_[index] : "<generated>";
            out += file + ":" + std::to_string(encoded % kLinesPerFile) + ": " + match[3].str() + "\n";
        } else if (!line.empty()) {
            out += line + "\n";
        }
    }
    return out;
}

}  // namespace fxview::effect
