#include "math/transform.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace fxview::math {

glm::mat4 rotation_matrix(const glm::quat& q) { return glm::mat4_cast(glm::normalize(q)); }

glm::mat4 world_matrix(const Pose& pose, const glm::vec3& scale) {
    return glm::translate(glm::mat4(1.0f), pose.position) * rotation_matrix(pose.rotation) *
           glm::scale(glm::mat4(1.0f), scale);
}

glm::mat4 view_matrix(const CameraPose& camera) {
    const glm::mat4 zoom = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -camera.distance));
    const glm::mat4 pan = glm::translate(glm::mat4(1.0f), glm::vec3(-camera.pan, 0.0f));
    return zoom * rotation_matrix(camera.rotation) * pan;
}

glm::mat3 normal_matrix(const glm::mat4& world) { return glm::transpose(glm::inverse(glm::mat3(world))); }

glm::vec3 camera_world_position(const CameraPose& camera) {
    return glm::vec3(glm::inverse(view_matrix(camera))[3]);
}

glm::quat rotation_from_euler_degrees(const glm::vec3& degrees) {
    const glm::vec3 r = glm::radians(degrees);
    // Intrinsic X then Y then Z equals the extrinsic product Rx·Ry·Rz.
    return glm::normalize(glm::angleAxis(r.x, glm::vec3(1, 0, 0)) * glm::angleAxis(r.y, glm::vec3(0, 1, 0)) *
                          glm::angleAxis(r.z, glm::vec3(0, 0, 1)));
}

glm::quat rotation_from_axis_angle(const glm::vec3& axis, float degrees) {
    return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

glm::mat4 perspective_matrix(float fov_y_degrees, float aspect, float near_plane, float far_plane) {
    return glm::perspective(glm::radians(fov_y_degrees), aspect, near_plane, far_plane);
}

}  // namespace fxview::math
