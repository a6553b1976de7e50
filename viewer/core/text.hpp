// Small text helpers shared by the parsers and file loaders.
#pragma once
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

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

// `text` without leading and trailing white space.
inline std::string trim(const std::string& text) {
    size_t begin = 0, end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    return text.substr(begin, end - begin);
}

// The white-space separated words of `text`.
inline std::vector<std::string> words(const std::string& text) {
    std::vector<std::string> out;
    size_t at = 0;
    while (true) {
        while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at]))) ++at;
        if (at == text.size()) return out;
        const size_t start = at;
        while (at < text.size() && !std::isspace(static_cast<unsigned char>(text[at]))) ++at;
        out.push_back(text.substr(start, at - start));
    }
}

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
