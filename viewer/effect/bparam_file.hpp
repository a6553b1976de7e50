// Disney BRDF Explorer's parameter files (`.bparam`), read and written as BRDF Explorer does: a first
// line `bparam FILE` naming the BRDF the values are for, then `::begin parameters` ... `::end
// parameters` with `float NAME MIN MAX VALUE`, `bool NAME 0|1` and `color NAME R G B` lines (`#`
// comments, blank lines). Opened as an effect, a .bparam loads FILE (relative to the .bparam's folder,
// else to the working folder, as BRDF Explorer) with the values as its parameters' defaults; names FILE
// has no parameter for are warned about and ignored, as BRDF Explorer ignores them. `--save-preset
// NAME.bparam` writes one.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core/limits.hpp"
#include "effect/brdf_file.hpp"
#include "effect/effect.hpp"
#include "effect/parameter_values.hpp"

namespace fxview::effect {

struct BparamFile {
    std::string path;
    std::string brdf;  // the file the values are for, resolved
    ParameterOverrides values;
    std::vector<std::string> warnings;  // "file:line: warning: ..."
};

bool is_bparam_file(const std::string& path);
// Throws EffectError at the offending line for a malformed file.
BparamFile read_bparam_file(const std::string& path, const ResourceLimits& limits = {});

// Writes `values` of `effect` (its float, bool and three-number colour parameters; others are left
// out) as a .bparam naming the effect's BRDF file. Throws Error when the file cannot be written.
void save_bparam_file(const std::string& path, const Effect& effect, const ParameterValues& values);

}  // namespace fxview::effect
