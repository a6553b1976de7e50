// The current values of an effect's editable parameters, starting from the file's defaults.
// Values are kept by parameter name, so that they can survive a reload of the effect.
#pragma once
#include <map>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "effect/effect.hpp"

namespace fxview::effect {

struct ParameterValues {
    std::map<std::string, std::vector<double>> numbers;  // every non-sampler parameter without a semantic
    std::map<std::string, std::string> textures;         // sampler -> file that replaces its ResourceName
};

ParameterValues default_values(const Effect& effect);  // zeros where the file gives no default

// Parses NAME=VALUE as the command line writes it: 0.5, 1,0,0, #rrggbb (sRGB hex, stored linear),
// true/false, a combo entry by name (its index), or a file path for a sampler. Throws UsageError naming the parameter for an unknown name or a malformed value.
void set_value_from_text(const Effect& effect, ParameterValues& values, const std::string& assignment);

// The one rule every value passes, whatever its source (--set, presets, the viewer, plugins, script
// verbs, a file's default): the parameter's number of components; finite numbers a float holds;
// whole numbers of a 32-bit int for int types, 0 or 1 for bool; a combo's index inside its list (a
// spectrum index inside the library); each component inside the hard range, which is HardMin/HardMax
// where the file declares them, else UIMin/UIMax. Returns why `value` breaks it, empty if it does not.
std::string value_problem(const Parameter& parameter, const std::vector<double>& value);
// A file's defaults pass the same rule (EffectError at the parameter otherwise). Legacy files'
// UIMin/UIMax were slider suggestions in FX Composer, and library files' defaults often lie outside
// them: there the range widens to hold the default.
void check_defaults(Effect& effect);
// The hard range of `parameter` (either end may be open).
std::pair<std::optional<double>, std::optional<double>> hard_range(const Parameter& parameter);

// Order constraints between parameters (UIAtLeast, e.g. Upper >= Lower for a wavelength range):
// check_constraints throws UsageError naming both values; enforce_constraints moves the other
// value to meet the one the user just changed (`changed`), as the viewer's sliders do.
void check_constraints(const Effect& effect, const ParameterValues& values);
void enforce_constraints(const Effect& effect, ParameterValues& values, const std::string& changed);

}  // namespace fxview::effect
