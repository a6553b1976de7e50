// Any BRDF lit by a sized scene light (a sphere, a disc, a rectangle): the GPU's estimate of
// ∫ f(l, v) cos θ L dω over the light (effects/lib/area_light_brdf.glsl: the light's points and a GGX
// lobe's directions, combined by the balance heuristic) in double, and the same integral by an
// independent rule (the midpoint rule over the light's own surface or disc of directions).
#pragma once
#include <functional>

#include <glm/glm.hpp>

#include "brdf/models.hpp"
#include "reference/reference.hpp"

namespace fxview::reference {

using BrdfTowards = std::function<glm::dvec3(const glm::dvec3& l)>;  // f(l, v) for the pixel's v, n, t

// Whether the input's light has a size (a sphere's radius, or a flat light).
bool light_is_sized(const ShadingInput& in);

// The GPU's sum per unit of the effect's light strength; `alpha` the lobe's rough GGX width as the
// technique passes it. `edge_slack` (optional) receives what float may move: the terms of lobe
// directions that pass within rounding of the light's outline (either side counts), and the change
// of the point count where the horizon test is that close.
glm::dvec3 area_light_brdf(const ShadingInput& in, const brdf::Directions& d, const BrdfTowards& f, double alpha, double* edge_slack = nullptr);

// What float may move the GPU's sum by, relative to its value, where the light comes close: each
// term's 1 / r² moves by about 2 δ / r for the float rounding δ (~6e-8 of coordinates of order 1) of
// the point's position, r its distance to the light's nearest point.
double near_light_rounding(const ShadingInput& in);

// The integral itself by two dense midpoint grids combined by the balance heuristic: the light (a
// sphere's disc of directions in 160 rings of equal solid angle x 320 azimuths, a flat disc in 128
// rings of equal area x 256 azimuths, a rectangle in 200 x 200 cells) and a cone of half-angle 8 α
// about the mirror direction (128 x 256 elements of equal solid angle), so that lobes sharper than
// the light's elements are resolved too.
glm::dvec3 area_light_brdf_integral(const ShadingInput& in, const brdf::Directions& d, const BrdfTowards& f, double alpha);

}  // namespace fxview::reference
