// Parameter presets (like BRDF Explorer's .bparam): every editable value of an effect in a small
// JSON file, {"effect": "...", "technique": "...", "parameters": {"Name": 0.5, "Color": [1,0,0],
// "Sampler": "file.png"}}.
#pragma once
#include <string>

#include "effect/parameter_values.hpp"

namespace fxview::effect {

struct Preset {
    std::string effect;     // informational: the effect file the values were made for
    std::string technique;  // may be empty
    ParameterValues values;
};

void save_preset(const std::string& path, const Effect& effect, const std::string& technique, const ParameterValues& values);
// Reads a preset and applies it over `values`; throws Error naming the file for bad JSON, an
// unknown parameter or a value of the wrong size.
Preset load_preset(const std::string& path, const Effect& effect, ParameterValues& values);

}  // namespace fxview::effect
