#include "ui/error_list.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <sstream>

extern char** environ;

namespace fxview::ui {

namespace {

// The place a message line starts with: the shortest prefix FILE followed by ":DIGITS:". A plain
// scan (compiler logs may hold very long lines; std::regex recursed per character).
bool leading_place(const std::string& line, std::string& file, int& number) {
    for (size_t colon = line.find(':'); colon != std::string::npos; colon = line.find(':', colon + 1)) {
        size_t end = colon + 1;
        while (end < line.size() && std::isdigit(static_cast<unsigned char>(line[end]))) ++end;
        if (colon == 0 || end == colon + 1 || end - colon > 10 || end >= line.size() || line[end] != ':') continue;
        file = line.substr(0, colon);
        number = std::stoi(line.substr(colon + 1, end - colon - 1));
        return true;
    }
    return false;
}

}  // namespace

std::vector<ErrorLocation> error_locations(const std::string& text) {
    std::vector<ErrorLocation> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::string file;
        int number = 0;
        if (!leading_place(line, file, number)) continue;
        std::error_code missing;
        if (!std::filesystem::is_regular_file(file, missing)) continue;  // "note:" lines and the like
        const auto seen = std::find_if(out.begin(), out.end(), [&](const ErrorLocation& e) { return e.file == file && e.line == number; });
        if (seen != out.end()) seen->message += "\n" + line;  // messages of one line stay one place
        else out.push_back({file, number, line});
    }
    return out;
}

std::string editor_file_argument(const std::string& file) {
    // An absolute path starts with '/', so no editor reads it as an option or a command ("+cmd" in
    // vi, "-x" anywhere); a relative name gets "./" for the same reason, resolved or not.
    std::error_code failed;
    const std::filesystem::path absolute = std::filesystem::absolute(file, failed);
    if (!failed && absolute.is_absolute()) return absolute.lexically_normal().string();
    return file.empty() || file.front() == '/' ? file : "./" + file;
}

std::vector<std::string> editor_command(const std::string& editor, const std::string& file, int line) {
    std::vector<std::string> words;
    std::istringstream in(editor);
    for (std::string word; in >> word;) words.push_back(word);
    if (words.empty()) return words;
    const std::string program = std::filesystem::path(words.front()).filename().string();
    const std::string safe_file = editor_file_argument(file);
    const std::string at = safe_file + ":" + std::to_string(line);
    if (program == "code" || program == "codium" || program == "code-insiders" || program == "code-oss") {
        words.insert(words.end(), {"--goto", at});
    } else if (program == "subl" || program == "sublime_text") {
        words.push_back(at);
    } else {
        words.insert(words.end(), {"+" + std::to_string(line), safe_file});
    }
    return words;
}

std::string open_in_editor(const std::string& file, int line) {
    const char* visual = std::getenv("VISUAL");
    const char* editor = visual && *visual ? visual : std::getenv("EDITOR");
    if (!editor || !*editor) return "set $VISUAL or $EDITOR to open " + file + ":" + std::to_string(line) + " in your editor";
    const std::vector<std::string> command = editor_command(editor, file, line);
    if (command.empty()) return "$VISUAL/$EDITOR is empty";
    std::vector<char*> argv;
    for (const auto& word : command) argv.push_back(const_cast<char*>(word.c_str()));
    argv.push_back(nullptr);
    pid_t child = 0;
    if (posix_spawnp(&child, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return std::string("cannot start ") + command.front();
    // Not waited for: the editor lives on; its exit is collected without blocking when the next one starts.
    while (waitpid(-1, nullptr, WNOHANG) > 0) {
    }
    return "opened " + file + ":" + std::to_string(line) + " with " + command.front();
}

}  // namespace fxview::ui
