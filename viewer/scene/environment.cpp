#include <cmath>
#include <numbers>

#include "scene/scene.hpp"

namespace fxview::scene {

glm::mat3 Environment::world_to_environment() const {
    // The environment turned by +angle about +Y: a world direction is turned back by -angle.
    const float a = -rotation_degrees * std::numbers::pi_v<float> / 180.0f, c = std::cos(a), s = std::sin(a);
    return glm::mat3(glm::vec3(c, 0.0f, -s), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(s, 0.0f, c));  // columns
}

}  // namespace fxview::scene
