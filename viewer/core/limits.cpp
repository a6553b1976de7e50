#include "core/limits.hpp"

#include <charconv>
#include <filesystem>

#include "core/error.hpp"

namespace fxview {

const std::vector<LimitInfo>& limit_infos() {
    static const std::vector<LimitInfo> infos = {
        {"array-elements", &ResourceLimits::array_elements, "elements of one uniform array"},
        {"texture-dimension", &ResourceLimits::texture_dimension, "pixels along a texture's side"},
        {"texture-bytes", &ResourceLimits::texture_bytes, "bytes of one decoded texture"},
        {"effect-texture-bytes", &ResourceLimits::effect_texture_bytes, "bytes of all textures of an effect"},
        {"data-file-bytes", &ResourceLimits::data_file_bytes, "bytes of one data file"},
        {"source-bytes", &ResourceLimits::source_bytes, "bytes of an effect with its includes"},
        {"compile-bytes", &ResourceLimits::compile_bytes, "bytes of GLSL compiled, over all passes"},
        {"include-depth", &ResourceLimits::include_depth, "nested #include levels"},
    };
    return infos;
}

static const LimitInfo& find_limit(const std::string& name) {
    for (const auto& info : limit_infos())
        if (name == info.name) return info;
    std::string names;
    for (const auto& info : limit_infos()) names += (names.empty() ? "" : ", ") + std::string(info.name);
    throw UsageError("unknown budget '" + name + "' (known: " + names + ")");
}

void set_limit(ResourceLimits& limits, const std::string& assignment) {
    const size_t equals = assignment.find('=');
    if (equals == std::string::npos) throw UsageError("--limit takes NAME=VALUE, got '" + assignment + "'");
    const LimitInfo& info = find_limit(assignment.substr(0, equals));
    const std::string text = assignment.substr(equals + 1);
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    std::string suffix(end, text.data() + text.size());
    const std::int64_t scale = suffix.empty() ? 1 : suffix == "K" || suffix == "k" ? 1ll << 10 : suffix == "M" ? 1ll << 20 : suffix == "G" ? 1ll << 30 : 0;
    if (error != std::errc() || text.empty() || scale == 0 || value < 0 || value > (std::int64_t{1} << 50) / scale)
        throw UsageError("--limit " + std::string(info.name) + " needs a non-negative integer (optionally K, M or G), got '" + text + "'");
    limits.*info.field = value * scale;
}

void check_limit(const ResourceLimits& limits, const char* name, std::int64_t value, const std::string& where,
                 const std::string& what) {
    const LimitInfo& info = find_limit(name);
    const std::int64_t limit = limits.*info.field;
    if (value > limit)
        throw BudgetError(where + ": " + what + " " + std::to_string(value) + " exceeds the budget " + info.name + " = " +
                    std::to_string(limit) + " (raise it with --limit " + info.name + "=N)");
}

std::string not_a_file(const std::string& path) {
    std::error_code error;
    return std::filesystem::exists(path, error) ? "not a regular file (a device, a pipe or a folder)" : "no such file";
}

std::int64_t checked_file_size(const std::string& path, const ResourceLimits& limits) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) throw Error(path + ": " + not_a_file(path));
    const auto size = static_cast<std::int64_t>(std::filesystem::file_size(path, error));
    if (error) throw Error(path + ": cannot read its size");
    check_limit(limits, "data-file-bytes", size, path, "file size");
    return size;
}

}  // namespace fxview
