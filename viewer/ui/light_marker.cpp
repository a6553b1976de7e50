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

LightOutline light_outline(const scene::Camera& camera, const scene::Light& light, glm::vec2 view_size) {
    LightOutline outline;
    if (!light.has_size()) return outline;
    const glm::mat4 to_clip = math::perspective_matrix(camera.fov_y_degrees, view_size.x / view_size.y, camera.near_plane, camera.far_plane) *
                              math::view_matrix(camera.pose);
    bool behind = false;
    const auto project = [&](const glm::dvec3& p) {
        const glm::vec4 clip = to_clip * glm::vec4(glm::vec3(p), 1.0f);
        if (clip.w <= 1e-6f) behind = true;
        const glm::vec2 ndc = glm::vec2(clip) / std::max(clip.w, 1e-6f);
        return glm::vec2((ndc.x * 0.5f + 0.5f) * view_size.x, (0.5f - ndc.y * 0.5f) * view_size.y);
    };
    scene::LightGeometry g = scene::light_geometry(light);
    outline.flat = g.shape != scene::LightShape::Sphere;
    if (!outline.flat) {  // the silhouette: a circle across the direction from the camera
        const glm::dvec3 view = glm::normalize(g.centre - glm::dvec3(math::camera_world_position(camera.pose)));
        const glm::dvec3 side = glm::cross(view, glm::dvec3(0, 1, 0));
        g.u = glm::length(side) > 1e-9 ? glm::normalize(side) : glm::dvec3(1, 0, 0);
        g.v = glm::cross(g.u, view);
    }
    for (const glm::dvec3& p : g.outline(48)) outline.points.push_back(project(p));
    outline.centre = project(g.centre);
    outline.facing = project(g.centre + g.normal * std::max(0.6 * std::max(g.half_size.x, g.half_size.y), 0.2));
    if (behind) outline = LightOutline{};
    return outline;
}

}  // namespace fxview::ui
