// An effect file with its #include lines replaced by the included files, remembering for every line
// where it came from. GLSL cut from it carries #line directives, so that compiler messages can be
// mapped back to `file:line` of the effect or the include.
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/limits.hpp"

namespace fxview::effect {

enum class ShaderStage { Vertex, Geometry, Fragment };
const char* stage_name(ShaderStage stage);

struct SourceLocation {
    std::string file;
    int line = 0;
    std::string str() const { return file + ":" + std::to_string(line); }
};

// Every problem with an effect: what() reads "file:line: message".
struct EffectError : Error {
    EffectError(SourceLocation where, const std::string& message)
        : Error(where.str() + ": " + message), location(std::move(where)) {}
    // Several messages, each already starting with its own `file:line:` (compiler output).
    struct Lines {};
    EffectError(SourceLocation where, const std::string& lines, Lines) : Error(lines), location(std::move(where)) {}
    SourceLocation location;
};

class SourceMap {
public:
    // Reads `path` and expands `#include "file"` (searched relative to the including file, then in
    // each of `include_dirs`). A file with `#pragma once` is expanded once; a cycle is an error
    // naming the chain. Included files must be allowed by `access`; nesting deeper than
    // limits.include_depth, or more than limits.source_bytes of text in all, is an error.
    static SourceMap load(const std::string& path, const std::vector<std::string>& include_dirs, const ResourceLimits& limits,
                          const FileAccessPolicy& access);

    const std::string& text() const { return text_; }
    SourceLocation locate(size_t offset) const;
    // The origin of the 1-based `line` of text().
    SourceLocation locate_line(int line) const;
    // Replaces the text by a version of it with the same lines (a preprocessor's output): every
    // line keeps its origin; surplus lines count as the last one.
    void replace_text(std::string text);
    // The text between two offsets as GLSL, with a #line directive wherever the origin jumps.
    std::string glsl(size_t begin, size_t end) const;
    // A #line directive that makes the next line count as `where`.
    std::string line_directive(const SourceLocation& where) const;
    // Rewrites a driver's info log ("0:12(3): error: ..." Mesa, "0(12) : error ..." NVIDIA)
    // into "file:line: error: ...".
    std::string map_compiler_log(const std::string& log) const;
    const std::vector<std::string>& files() const { return files_; }
    // What a translated file (.brdf) accepted with a warning, "file:line: warning: ...".
    const std::vector<std::string>& warnings() const { return warnings_; }
    // Whether `line` starts with "FILE:" for one of the files (a mapped compiler message).
    bool has_file_prefix(const std::string& line) const;

private:
    struct LineOrigin {
        int file;
        int line;
    };
    struct LoadContext {
        const std::vector<std::string>& include_dirs;
        const ResourceLimits& limits;
        const FileAccessPolicy& access;
        std::map<std::string, struct ParameterOverride>* overrides = nullptr;  // a .bparam's values for the .brdf it names
    };
    void append_file(const std::string& path, const LoadContext& context, std::vector<std::string>& stack,
                     const SourceLocation* included_from);
    size_t line_index(size_t offset) const;
    int file_index(const std::string& name) const;

    std::string text_;
    std::vector<size_t> line_starts_;
    std::vector<LineOrigin> origins_;
    std::vector<std::string> files_, warnings_;
    std::set<std::string> once_;  // canonical paths of `#pragma once` files already expanded
};

}  // namespace fxview::effect
