#include "math/arcball.hpp"

#include <algorithm>
#include <cmath>

namespace fxview::math {

glm::vec3 arcball_point(const glm::vec2& ndc) {
    const float r2 = glm::dot(ndc, ndc);
    if (r2 > 1.0f) {
        const glm::vec2 rim = ndc / std::sqrt(r2);
        return {rim, 0.0f};
    }
    return {ndc, std::sqrt(1.0f - r2)};
}

glm::quat arcball_rotation(const glm::vec2& from, const glm::vec2& to) {
    const glm::vec3 a = arcball_point(from), b = arcball_point(to);
    const glm::vec3 axis = glm::cross(a, b);
    const float length = glm::length(axis);
    if (length < 1e-7f) return glm::quat(1, 0, 0, 0);
    const float angle = std::atan2(length, std::clamp(glm::dot(a, b), -1.0f, 1.0f));
    return glm::angleAxis(angle, axis / length);
}

glm::quat rotate_in_view(const glm::quat& orientation, const glm::quat& view_rotation, const glm::quat& camera_rotation) {
    // World -> view is camera_rotation; conjugating the drag brings it into world space.
    return glm::normalize(glm::inverse(camera_rotation) * view_rotation * camera_rotation * orientation);
}

}  // namespace fxview::math
