// Parameter presets: every editable value of an effect in a small JSON file, {"effect": "...",
// "technique": "...", "parameters": {"Name": 0.5, "Color": [1,0,0], "Sampler": "file.png"}}; or, for
// a path ending in .bparam, BRDF Explorer's parameter file (bparam_file.hpp).
#pragma once
#include <map>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "core/file_access.hpp"
#include "core/limits.hpp"

#include "effect/parameter_values.hpp"

namespace fxview::effect {

struct Preset {
    std::string effect;     // informational: the effect file the values were made for
    std::string technique;  // may be empty
    ParameterValues values;
    std::vector<std::string> warnings;  // "file:line: warning: ..." (a .bparam's names the effect lacks)
};

void save_preset(const std::string& path, const Effect& effect, const std::string& technique, const ParameterValues& values);
// The scene and display settings a preset may carry besides its values, {"scene": {"environment":
// "studio", "environment_rotate": 0, "environment_intensity": 1, "exposure": 0, "tone_map":
// "pbr-neutral", "samples": 4, "light_shape": "disc", "light_radius": 0.5, "light_size": [2, 1],
// "light_spectrum": "F11", "light_intensity": "500lx"}}: what the CLI and the viewer use unless told otherwise. Error naming
// file and line for a wrong type, a value out of range or an unknown key. Environment files resolve
// from the preset's folder and must be readable under `access` (the effect's policy; the preset's
// folder is added), as an effect's textures.
struct PresetScene {
    std::optional<std::string> environment, tone_map, light_spectrum, light_shape, light_intensity;
    std::optional<float> environment_rotate, environment_intensity, exposure, light_radius;
    std::optional<glm::vec2> light_size;  // a rectangle light's width and height
    std::optional<int> samples;
    std::string effect;  // the preset's "effect", as written ("" if none)
    std::string path;
    std::map<std::string, int> lines;  // the line of each key, for messages about its value
    std::string where(const std::string& key) const;  // "PATH:LINE: "
};
PresetScene load_preset_scene(const std::string& path, const ResourceLimits& limits = {}, FileAccessPolicy access = {});

// Reads a preset and applies it over `values`; throws Error naming the file for bad JSON, an
// unknown parameter or a value of the wrong size.
Preset load_preset(const std::string& path, const Effect& effect, ParameterValues& values);

}  // namespace fxview::effect
