// Small text helpers shared by the parsers and file loaders.
#pragma once
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace fxview {

inline std::string to_lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// ".png" for "Some/File.PNG": extensions compare case-insensitively everywhere.
inline std::string lower_extension(const std::string& path) {
    return to_lower(std::filesystem::path(path).extension().string());
}

}  // namespace fxview
