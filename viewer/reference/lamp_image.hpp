// The scene light seen along one direction (effects/lib/area_light.glsl's scene_light_radiance): a
// sized light's radiance per unit of the effect's light strength, its image blurred by an angle: a
// sphere's disc measured by chords (optics/grating_orders.hpp), a flat light's outline
// (scene/light_geometry.hpp); 0 for a point. What the films mirror.
#pragma once
#include <glm/glm.hpp>

#include "reference/reference.hpp"

namespace fxview::reference {

double scene_light_radiance(const ShadingInput& in, const glm::dvec3& direction, double width);

}  // namespace fxview::reference
