// Arcball rotation (Shoemake): a drag on the screen turns the view-space sphere under the cursor.
// Points are in normalised device coordinates, x right and y up, the ball of radius 1 centred.
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace fxview::math {

// The point on the unit ball under `ndc`; outside the ball, the nearest point on its rim.
glm::vec3 arcball_point(const glm::vec2& ndc);
// The rotation that carries the ball point under `from` to the one under `to` (view space).
glm::quat arcball_rotation(const glm::vec2& from, const glm::vec2& to);
// Applies a view-space rotation to a world-space orientation seen through `camera_rotation`:
// the object turns on screen the way the mouse moved.
glm::quat rotate_in_view(const glm::quat& orientation, const glm::quat& view_rotation, const glm::quat& camera_rotation);

}  // namespace fxview::math
