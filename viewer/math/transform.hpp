// The transforms of the original ShaderViewer (seed 002, eq. 52-54) in GLM's column-vector
// convention. The thesis writes row vectors (v' = v·M), so its eq. 52 is the transpose of
// glm::mat4_cast(q), and its products read right to left here:
//   eq. 53  world = T(position) · R(q) · S     (rotate about the object's own origin, then move)
//   eq. 54  view  = T_z(-distance) · R(q) · T_xy(-pan)   (Z translation is a zoom that ignores rotation)
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace fxview::math {

struct Pose {
    glm::vec3 position{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
};

// Camera that orbits its target: `rotation` turns the world in front of it, `distance` zooms.
struct CameraPose {
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec2 pan{0.0f};  // target point in the rotated XY plane
    float distance = 3.0f;
};

glm::mat4 rotation_matrix(const glm::quat& q);                        // eq. 52 (transposed)
glm::mat4 world_matrix(const Pose& pose, const glm::vec3& scale);    // eq. 53
glm::mat4 view_matrix(const CameraPose& camera);                      // eq. 54
glm::mat3 normal_matrix(const glm::mat4& world);                      // inverse transpose of the 3x3 part
glm::vec3 camera_world_position(const CameraPose& camera);

// Intrinsic rotations in degrees about X, then Y, then Z (the order a user types them in).
glm::quat rotation_from_euler_degrees(const glm::vec3& degrees);
glm::quat rotation_from_axis_angle(const glm::vec3& axis, float degrees);

glm::mat4 perspective_matrix(float fov_y_degrees, float aspect, float near_plane, float far_plane);

}  // namespace fxview::math
