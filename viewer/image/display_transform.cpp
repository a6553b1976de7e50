#include "image/display_transform.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "image/image.hpp"

namespace fxview::image {
namespace {

glm::vec3 aces_fitted(glm::vec3 c) {
    // sRGB -> ACES input (RRT_SAT folded in), the RRT + ODT fit, back to sRGB (Hill's matrices, rows as written).
    const glm::mat3 input = glm::transpose(glm::mat3(0.59719f, 0.35458f, 0.04823f, 0.07600f, 0.90834f, 0.01566f, 0.02840f, 0.13383f, 0.83777f));
    const glm::mat3 output = glm::transpose(glm::mat3(1.60475f, -0.53108f, -0.07367f, -0.10208f, 1.10813f, -0.00605f, -0.00327f, -0.07276f, 1.07602f));
    c = input * c;
    c = (c * (c + 0.0245786f) - 0.000090537f) / (c * (0.983729f * c + 0.4329510f) + 0.238081f);
    return output * c;
}

glm::vec3 pbr_neutral(glm::vec3 c) {
    const float start = 0.8f - 0.04f, desaturation = 0.15f;
    const float x = std::min(c.r, std::min(c.g, c.b));
    const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    c -= offset;
    const float peak = std::max(c.r, std::max(c.g, c.b));
    if (peak < start) return c;
    const float d = 1.0f - start;
    const float new_peak = 1.0f - d * d / (peak + d - start);
    c *= new_peak / peak;
    const float g = 1.0f - 1.0f / (desaturation * (peak - new_peak) + 1.0f);
    return glm::mix(c, glm::vec3(new_peak), g);
}

}  // namespace

ToneMap parse_tone_map(const std::string& name) {
    if (name == "none") return ToneMap::None;
    if (name == "aces") return ToneMap::Aces;
    if (name == "pbr-neutral") return ToneMap::PbrNeutral;
    throw UsageError("unknown tone mapper '" + name + "' (none, aces or pbr-neutral)");
}

const char* tone_map_name(ToneMap tone_map) {
    switch (tone_map) {
        case ToneMap::Aces: return "aces";
        case ToneMap::PbrNeutral: return "pbr-neutral";
        default: return "none";
    }
}

glm::vec3 display_transform(glm::vec3 c, const DisplaySettings& settings) {
    c = glm::max(c, glm::vec3(0.0f)) * std::exp2(settings.exposure_ev);
    if (settings.tone_map == ToneMap::Aces) c = aces_fitted(c);
    else if (settings.tone_map == ToneMap::PbrNeutral) c = pbr_neutral(c);
    return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

void apply_display_transform(FloatImage& image, const DisplaySettings& settings) {
    if (image.channels < 3) return;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            float* p = image.pixel(x, y);
            const glm::vec3 shown = display_transform(glm::vec3(p[0], p[1], p[2]), settings);
            p[0] = shown.r;
            p[1] = shown.g;
            p[2] = shown.b;
        }
}

const char* const kDisplayTransformGlsl = R"(
vec3 display_transform(vec3 c, float exposure_ev, int tone_map) {
    c = max(c, vec3(0.0)) * exp2(exposure_ev);
    if (tone_map == 1) {
        const mat3 aces_in = transpose(mat3(0.59719, 0.35458, 0.04823, 0.07600, 0.90834, 0.01566, 0.02840, 0.13383, 0.83777));
        const mat3 aces_out = transpose(mat3(1.60475, -0.53108, -0.07367, -0.10208, 1.10813, -0.00605, -0.00327, -0.07276, 1.07602));
        c = aces_in * c;
        c = (c * (c + 0.0245786) - 0.000090537) / (c * (0.983729 * c + 0.4329510) + 0.238081);
        c = aces_out * c;
    } else if (tone_map == 2) {
        const float start = 0.8 - 0.04, desaturation = 0.15;
        float x = min(c.r, min(c.g, c.b));
        float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
        c -= offset;
        float peak = max(c.r, max(c.g, c.b));
        if (peak >= start) {
            float d = 1.0 - start;
            float new_peak = 1.0 - d * d / (peak + d - start);
            c *= new_peak / peak;
            float g = 1.0 - 1.0 / (desaturation * (peak - new_peak) + 1.0);
            c = mix(c, vec3(new_peak), g);
        }
    }
    return clamp(c, 0.0, 1.0);
}
)";

}  // namespace fxview::image
