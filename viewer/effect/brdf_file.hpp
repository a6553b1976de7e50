// Disney BRDF Explorer's `.brdf` files as effects. The format: a first line `analytic`; `#` comments;
// `::begin parameters` ... `::end parameters` with one parameter a line (`float NAME MIN MAX
// DEFAULT`, `color NAME R G B`, `bool NAME DEFAULT`); `::begin shader` ... `::end shader`, GLSL that
// defines `vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)`. The file becomes effect text line by
// line, each line remembering the line of the .brdf it came from (so that compiler messages name the
// .brdf's lines): parameters become annotated uniforms, the shader block top-level GLSL, and
// effects/lib/brdf_file.glsl adds the techniques that render BRDF() (docs/effect-format.md).
#pragma once
#include <string>
#include <vector>

namespace fxview::effect {

struct TranslatedLines {
    std::vector<std::string> lines;
    std::vector<int> origins;  // line of the .brdf file each line came from (1-based)
};

bool is_brdf_file(const std::string& path);
// Throws EffectError at the offending line of `path` for a malformed file.
TranslatedLines translate_brdf_file(const std::string& path, const std::vector<std::string>& lines);

}  // namespace fxview::effect
