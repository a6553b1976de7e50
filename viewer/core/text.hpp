// Small text helpers shared by the parsers and file loaders.
#pragma once
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

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

namespace fxview {

// Text from a file as it may appear inside a message: at most `max_chars` characters (longer text
// ends in "..."), control characters as '?', so that one hostile token can neither flood a terminal
// nor hide in it. Bytes of UTF-8 sequences are kept (labels may say "κ").
inline std::string excerpt(std::string_view text, size_t max_chars = 40) {
    std::string out;
    for (size_t i = 0; i < text.size() && i < max_chars; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        out += (c >= 0x20 && c != 0x7f) ? static_cast<char>(c) : '?';
    }
    if (text.size() > max_chars) out += "...";
    return out;
}

// excerpt() line by line: a message of several lines (compiler output) keeps its line breaks.
inline std::string excerpt_lines(std::string_view text, size_t max_chars_per_line = 4000) {
    std::string out;
    for (size_t start = 0; start <= text.size();) {
        const size_t end = std::min(text.find('\n', start), text.size());
        if (!out.empty()) out += '\n';
        out += excerpt(text.substr(start, end - start), max_chars_per_line);
        start = end + 1;
    }
    return out;
}

}  // namespace fxview
