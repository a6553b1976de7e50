// The display transform from scene-referred linear values to what a screen shows: exposure (in EV
// stops, a factor 2^EV) and then a tone mapper, before the sRGB encoding. The same arithmetic runs in
// C++ (PNG files of the CLI) and GLSL (the viewer's display pass, spliced from kDisplayTransformGlsl),
// so a PNG written by `fxview render` matches the window. EXR and PFM files stay scene-linear.
//   none         clamp to [0, 1] (the old behaviour)
//   aces         the ACES filmic curve, Stephen Hill's fit of the RRT + sRGB ODT (desaturates highlights)
//   pbr-neutral  Khronos PBR Neutral (2024): below 0.76 only a toe offset of 0.04 is taken off, highlights compress
#pragma once
#include <string>

#include <glm/glm.hpp>

namespace fxview::image {

enum class ToneMap { None = 0, Aces = 1, PbrNeutral = 2 };

struct DisplaySettings {
    float exposure_ev = 0.0f;
    ToneMap tone_map = ToneMap::None;
};

ToneMap parse_tone_map(const std::string& name);  // UsageError listing the names
const char* tone_map_name(ToneMap tone_map);
// Display-linear values in [0, 1] (sRGB encoding follows).
glm::vec3 display_transform(glm::vec3 linear, const DisplaySettings& settings);

struct FloatImage;
// Every pixel's RGB through display_transform (alpha kept).
void apply_display_transform(FloatImage& image, const DisplaySettings& settings);

// GLSL: vec3 display_transform(vec3 linear, float exposure_ev, int tone_map), tone_map as ToneMap.
extern const char* const kDisplayTransformGlsl;

}  // namespace fxview::image
