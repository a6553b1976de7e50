// CPU references: for every technique that fxview ships, an independent C++ implementation in
// double precision, written from the physics (not a line-by-line copy of the GLSL). It shades one
// pixel from the fragment inputs the GPU captured in the same draw (docs/cpu-reference.md).
#pragma once
#include <array>
#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "effect/parameter_values.hpp"
#include "reference/cpu_sampler.hpp"
#include "render/effect_resources.hpp"
#include "scene/scene.hpp"

namespace fxview::reference {

struct ShadingInput {
    glm::dvec3 position{0.0};  // world space
    glm::dvec3 normal{0.0};    // interpolated, not normalised
    glm::dvec2 uv{0.0};
    glm::dvec3 tangent{0.0};   // interpolated, not normalised
    glm::dvec3 camera{0.0};    // world-space camera position
    glm::dvec3 light{0.0};     // world-space light position
    double light_radius = 0;   // of a sphere light (as LIGHTRADIUS gives it); 0: a point light or a flat one
    scene::LightGeometry lamp; // the light's shape (a flat light: lamp.is_flat())
    // What the technique captured besides (capture.glsl's attachment 5); for cd.fx's Grating the
    // pixel's extent in path difference (nm) across and along the tracks, for its Orders how far the
    // view direction and the track direction turn across the pixel (radians).
    glm::dvec4 footprint{0.0};
};

// What a reference may read besides the pixel's inputs: the parameter values and the same
// texture data the GPU sampled (quantised alike).
struct ReferenceContext {
    const effect::ParameterValues& values;
    const render::EffectResources& resources;
    // The scene's environment (rotation, intensity) whose maps resources.environment() holds; null: none.
    const scene::Environment* environment = nullptr;

    double number(const std::string& name) const;  // first component of a parameter; Error if absent
    const spectral::PackedTexture& generated(const std::string& texture) const;
    // A sampler parameter's texture read by GL's rules through the CPU sampler (cpu_sampler.hpp),
    // from the data exactly as uploaded; Error if the effect has no such sampler.
    glm::dvec4 sample_2d(const std::string& sampler, glm::dvec2 uv) const;
    glm::dvec4 sample_3d(const std::string& sampler, glm::dvec3 str, double* footprint_spread = nullptr) const;
    glm::ivec3 texture_size(const std::string& sampler) const;  // width, height, depth of its base level
    CubeSample sample_cube(const std::string& sampler, glm::dvec3 direction) const;
};

using Shader = std::function<std::array<double, 4>(const ShadingInput&, const ReferenceContext&)>;

struct Reference {
    Shader shade;
    double tolerance = 1e-4;  // largest float difference allowed per channel
    std::string why;          // where the tolerance comes from
    // Where the tolerance depends on parameter values (e.g. the weight of a texture term): replaces
    // `tolerance` when set.
    std::function<double(const ReferenceContext&)> tolerance_for;
    // Extra error allowed at one pixel, from the technique's own sensitivity to float rounding of its
    // inputs: at a discontinuity (PathDifference's frac()) float and double may land on either side
    // of the jump; in a sharp highlight a few ulps of a cosine move the value by more than the
    // tolerance. Empty: none.
    std::function<double(const ShadingInput&, const ReferenceContext&)> slack;
    // Where the technique approximates an integral (image-based lighting's split sum): the integral
    // itself by Monte Carlo, for `compare --ground-truth`; `seed` varies the sample set per pixel.
    // Empty: the technique is exact up to float rounding.
    std::function<std::array<double, 4>(const ShadingInput&, const ReferenceContext&, unsigned seed)> truth;
    std::string truth_method = "the Monte Carlo integral";  // what `truth` computes, as compare names it
    // `truth` integrates a sphere light too: it runs without an environment when the light has a size.
    bool truth_with_sized_light = false;
    // Without an environment `truth` has no noise of its own (a quadrature, not Monte Carlo): computed once.
    bool truth_deterministic_without_environment = false;
    // Whether the truth measures an approximation of its own in this context even without an environment
    // or a sized light (a film's thickness spread); empty: no.
    std::function<bool(const ReferenceContext&)> truth_wanted;
};

// The largest change of any colour channel when the pixel's normal turns by `angle` (radians) in
// either of two directions across it: the GPU's normalised normal and the cosines formed from it
// carry a few ulps of rounding (~3e-7), which a steep highlight (pow of a cosine to a high power)
// amplifies. A slack for references whose value is steep in the angles.
double normal_sensitivity(const Shader& shade, const ShadingInput& in, const ReferenceContext& c, double angle = 1e-6);

// The reference for technique `technique` of the effect file named `effect_stem` (file name without
// extension), or nullptr if there is none.
const Reference* find_reference(const std::string& effect_stem, const std::string& technique);

}  // namespace fxview::reference
