// The ray through each pixel centre of a scene's camera in world space (double precision), from
// the same view and projection matrices the renderer uses; rows run from the top of the image.
#pragma once
#include <glm/glm.hpp>

#include "math/transform.hpp"
#include "scene/scene.hpp"

namespace fxview::test {

struct PixelRays {
    PixelRays(const scene::Camera& camera, int width, int height)
        : eye(math::camera_world_position(camera.pose)),
          inverse(glm::inverse(glm::dmat4(math::perspective_matrix(camera.fov_y_degrees, static_cast<float>(width) / height,
                                                                   camera.near_plane, camera.far_plane)) *
                               glm::dmat4(math::view_matrix(camera.pose)))),
          width(width),
          height(height) {}

    glm::dvec3 direction(int x, int y) const {
        const glm::dvec2 ndc(2.0 * (x + 0.5) / width - 1.0, 1.0 - 2.0 * (y + 0.5) / height);
        const glm::dvec4 far_point = inverse * glm::dvec4(ndc, 1.0, 1.0);
        return glm::normalize(glm::dvec3(far_point) / far_point.w - eye);
    }

    glm::dvec3 eye;
    glm::dmat4 inverse;
    int width, height;
};

}  // namespace fxview::test
