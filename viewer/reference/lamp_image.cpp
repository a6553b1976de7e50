#include "reference/lamp_image.hpp"

#include <algorithm>

#include "optics/grating_orders.hpp"

namespace fxview::reference {

double scene_light_radiance(const ShadingInput& in, const glm::dvec3& direction, double width) {
    if (in.lamp.is_flat()) return scene::flat_light_radiance(in.lamp, in.position, direction, width);
    if (!(in.light_radius > 0.0)) return 0.0;
    const glm::dvec3 to_light = in.light - in.position;
    const double distance = glm::length(to_light);
    return optics::sphere_light_radiance(glm::length(direction - to_light / distance), optics::light_edge_chord(in.light_radius / distance),
                                         std::max(width, 1e-6));
}

}  // namespace fxview::reference
