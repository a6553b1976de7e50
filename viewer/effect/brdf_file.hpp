// Disney BRDF Explorer's `.brdf` files as effects, read as BRDF Explorer reads them. The format: a
// first line `analytic` (further words on it are ignored); `#` comments;
// `::begin parameters` ... `::end parameters` with one parameter a line (`float NAME MIN MAX
// DEFAULT`, `color NAME R G B`, `bool NAME DEFAULT`); `::begin shader` ... `::end shader`, GLSL that
// defines `vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)` (a file that ends inside it ends it);
// other `::begin NAME` sections (the importance-sampling `isFunc`) are skipped with a warning, as
// BRDF Explorer skips what it does not know. The file becomes effect text line by
// line, each line remembering the line of the .brdf it came from (so that compiler messages name the
// .brdf's lines): parameters become annotated uniforms, the shader block top-level GLSL, and
// effects/lib/brdf_file.glsl adds the techniques that render BRDF() (docs/effect-format.md).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "effect/source_map.hpp"

namespace fxview::effect {

struct TranslatedLines {
    std::vector<std::string> lines;
    std::vector<int> origins;  // line of the .brdf file each line came from (1-based)
    // What BRDF Explorer would accept but fxview does not use or had to assume, "file:line: warning: ...".
    std::vector<std::string> warnings;
};

// A value given for a parameter from outside the file (a .bparam's, bparam_file.hpp), replacing its
// default; `used` is set when the file has a parameter of that name and type.
struct ParameterOverride {
    std::string type;                  // float, bool or color
    std::vector<std::string> numbers;  // as written: one for float and bool, three for color
    SourceLocation where;
    bool used = false;
};
using ParameterOverrides = std::map<std::string, ParameterOverride>;

bool is_brdf_file(const std::string& path);
// Throws EffectError at the offending line of `path` (or of the override) for a malformed file.
TranslatedLines translate_brdf_file(const std::string& path, const std::vector<std::string>& lines, ParameterOverrides* overrides = nullptr);

}  // namespace fxview::effect
