// Errors as a list of places: the `file:line:` messages of a failed load or compile, each of which
// opens the file at that line in the user's editor ($VISUAL, else $EDITOR).
#pragma once
#include <string>
#include <vector>

namespace fxview::ui {

struct ErrorLocation {
    std::string file;
    int line = 0;
    std::string message;  // the whole message line
};

// Every place `FILE:LINE:` that a line of `text` starts with (an effect error, a GLSL error mapped
// to the effect's file, a texture error with a line); messages of the same place are joined.
std::vector<ErrorLocation> error_locations(const std::string& text);

// The command that opens `file` at `line` in `editor` (a program with optional arguments, as in
// $EDITOR): `--goto FILE:LINE` for VS Code and its kin, `FILE:LINE` for Sublime Text, else the
// `+LINE FILE` that vi, vim, emacs, nano, gedit and kate understand.
// `file` as an editor must receive it: an absolute path (or "./NAME"), never a word that starts
// with '+' or '-' (vi runs "+!cmd" as a command; any editor reads "-x" as an option).
std::string editor_file_argument(const std::string& file);

std::vector<std::string> editor_command(const std::string& editor, const std::string& file, int line);

// Starts the editor of $VISUAL or $EDITOR without waiting for it. Returns what to tell the user.
std::string open_in_editor(const std::string& file, int line);

}  // namespace fxview::ui
