#include "ui/light_marker.hpp"

#include <algorithm>
#include <cmath>

#include "math/transform.hpp"

namespace fxview::ui {

LightMarker light_marker(const scene::Camera& camera, glm::vec3 light_position, glm::vec2 view_size, float margin) {
    LightMarker marker;
    const glm::vec2 centre = view_size * 0.5f;
    const glm::vec4 in_camera = math::view_matrix(camera.pose) * glm::vec4(light_position, 1.0f);
    const glm::mat4 projection = math::perspective_matrix(camera.fov_y_degrees, view_size.x / view_size.y, camera.near_plane, camera.far_plane);
    const glm::vec4 clip = projection * in_camera;
    if (clip.w > 1e-6f) {
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        marker.at = glm::vec2((ndc.x * 0.5f + 0.5f) * view_size.x, (0.5f - ndc.y * 0.5f) * view_size.y);
        if (marker.at.x >= 0 && marker.at.y >= 0 && marker.at.x <= view_size.x && marker.at.y <= view_size.y) return marker;
    }
    // Off screen: the edge point in the direction of the light as seen along the view axis (its
    // camera-space x, y; for a light behind the camera that is still where to turn to see it).
    marker.on_screen = false;
    marker.behind = in_camera.z > 1e-4f * glm::length(glm::vec3(in_camera));  // the camera looks along -z
    glm::vec2 d(in_camera.x, -in_camera.y);
    if (glm::length(d) < 1e-6f) d = glm::vec2(0.0f, 1.0f);  // straight behind: the bottom edge
    marker.direction = glm::normalize(d);
    const glm::vec2 half = glm::max(centre - margin, glm::vec2(1.0f));
    const float scale = std::min(std::abs(marker.direction.x) > 1e-6f ? half.x / std::abs(marker.direction.x) : INFINITY,
                                 std::abs(marker.direction.y) > 1e-6f ? half.y / std::abs(marker.direction.y) : INFINITY);
    marker.at = centre + marker.direction * scale;
    return marker;
}

}  // namespace fxview::ui
