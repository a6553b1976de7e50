// A flat scene light (a disc or a rectangle, scene/light_geometry.hpp) lighting wavelength.fx's lobes
// and the CD's diffuse coating: the factors that replace the point light's cos θ, (r·v)^p and (n·h)^p,
// as the GPU sums them over the light's points (effects/lib/area_light.glsl), and the integrals they
// stand for by an independent rule.
#pragma once
#include <glm/glm.hpp>

#include "reference/sphere_lamp.hpp"
#include "scene/light_geometry.hpp"

namespace fxview::reference {

// The GPU's sum (`rounding`: the relative float error of each lobe's base and of the point count; either sign).
LampFactors flat_lamp_factors(const scene::LightGeometry& light, const glm::dvec3& position, const glm::dvec3& n, const glm::dvec3& v,
                              double power, bool lobes, double rounding = 0.0);

// The same integrals by the midpoint rule over the light's own surface (a disc in 96 rings of equal
// width x 192 azimuths, a rectangle in 160 x 160 cells), each element weighted by its solid angle.
LampFactors flat_lamp_integral(const scene::LightGeometry& light, const glm::dvec3& position, const glm::dvec3& n, const glm::dvec3& v,
                               double power);

}  // namespace fxview::reference
