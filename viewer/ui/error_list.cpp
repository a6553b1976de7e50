#include "ui/error_list.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>

extern char** environ;

namespace fxview::ui {

std::vector<ErrorLocation> error_locations(const std::string& text) {
    std::vector<ErrorLocation> out;
    static const std::regex place(R"(^(.+?):(\d+):)");
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::smatch m;
        if (!std::regex_search(line, m, place)) continue;
        std::error_code missing;
        if (!std::filesystem::is_regular_file(m[1].str(), missing)) continue;  // "note:" lines and the like
        const int number = std::stoi(m[2].str());
        const auto seen = std::find_if(out.begin(), out.end(), [&](const ErrorLocation& e) { return e.file == m[1].str() && e.line == number; });
        if (seen != out.end()) seen->message += "\n" + line;  // messages of one line stay one place
        else out.push_back({m[1].str(), number, line});
    }
    return out;
}

std::vector<std::string> editor_command(const std::string& editor, const std::string& file, int line) {
    std::vector<std::string> words;
    std::istringstream in(editor);
    for (std::string word; in >> word;) words.push_back(word);
    if (words.empty()) return words;
    const std::string program = std::filesystem::path(words.front()).filename().string();
    const std::string at = file + ":" + std::to_string(line);
    if (program == "code" || program == "codium" || program == "code-insiders" || program == "code-oss") {
        words.insert(words.end(), {"--goto", at});
    } else if (program == "subl" || program == "sublime_text") {
        words.push_back(at);
    } else {
        words.insert(words.end(), {"+" + std::to_string(line), file});
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
