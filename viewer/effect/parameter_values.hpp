// The current values of an effect's editable parameters, starting from the file's defaults.
// Values are kept by parameter name, so that they can survive a reload of the effect.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "effect/effect.hpp"

namespace fxview::effect {

using ParameterValues = std::map<std::string, std::vector<double>>;

ParameterValues default_values(const Effect& effect);  // zeros where the file gives no default

// Parses NAME=VALUE as the command line writes it: 0.5, 1,0,0, #rrggbb (sRGB hex, stored linear),
// true/false. Throws UsageError naming the parameter for an unknown name or a malformed value.
void set_value_from_text(const Effect& effect, ParameterValues& values, const std::string& assignment);

}  // namespace fxview::effect
