// Reading effect files (docs/effect-format.md) into effect::Effect. Every error is an EffectError
// with the `file:line` of the effect or include where it was found.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core/file_access.hpp"
#include "core/limits.hpp"
#include "effect/effect.hpp"

namespace fxview::effect {

struct LoadOptions {
    std::vector<std::string> include_dirs;  // searched after the including file's folder (effects/lib)
    // Folders every effect may read besides its own (search roots, --allow-path); the effect's
    // folder is added when it loads.
    FileAccessPolicy access;
    ResourceLimits limits;
    // Combo entries filled in by the application: a parameter whose UIItems is exactly one of these
    // keys (e.g. "spectral:library") gets the list (e.g. the library's spectrum names).
    std::map<std::string, std::vector<std::string>> item_lists;
    // Legacy (Cg/HLSL) effects: "row" or "column" overrides how their matrices multiply vectors
    // (docs/legacy-effects.md); empty: the effect's annotation, its use of mul(), its file kind.
    std::string matrix_convention;
};

Effect load_effect(const std::string& path, const LoadOptions& options);

// Number of float/int components of a GLSL value type (float 1, vec3 3, mat4 16); 0 for samplers
// and anything that takes no constant.
int component_count(const std::string& glsl_type);
bool is_sampler_type(const std::string& glsl_type);

UiHints ui_hints_from(const std::vector<Annotation>& annotations);

}  // namespace fxview::effect
