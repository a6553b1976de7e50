// SAS semantics: uniforms the application fills every draw (matrices, camera, light, time).
// Matrix semantics are WORLD, VIEW, PROJECTION, WORLDVIEW, VIEWPROJECTION, WORLDVIEWPROJECTION,
// each also with the suffix INVERSE, TRANSPOSE or INVERSETRANSPOSE; VIEWLIGHTPOSITION is the light
// in eye space (Cg's glstate.light[0].position); LIGHTRADIUS, LIGHTSHAPE, LIGHTHALFSIZE, LIGHTFRAME and
// LIGHTRADIANCE describe a sized light (FrameContext).
#pragma once
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace fxview::effect {

struct FrameContext {
    glm::mat4 world{1.0f}, view{1.0f}, projection{1.0f};
    glm::vec3 camera_position{0.0f};
    glm::vec3 light_position{0.0f};
    float light_radius = 0.0f;  // 0: a point light; a flat light's equivalent (scene/light_geometry.hpp)
    // The light's shape (scene/light_geometry.hpp): LIGHTSHAPE 0 sphere or point, 1 disc, 2 rectangle;
    // LIGHTHALFSIZE a flat light's half extents; LIGHTFRAME its axes u, v and emitting normal as
    // columns; LIGHTRADIANCE its radiance per unit intensity (0: not a flat light).
    float light_shape = 0.0f;
    glm::vec2 light_half_size{0.0f};
    glm::mat3 light_frame{1.0f};
    float light_radiance = 0.0f;
    glm::vec2 viewport_size{1.0f};
    glm::mat3 environment_rotation{1.0f};  // world -> environment directions
    float environment_intensity = 0.0f;    // 0 without an environment
    float time = 0.0f;
    int frame = 0;
};

bool is_known_semantic(const std::string& semantic);  // upper case

// The value of a semantic as floats in GL order (column-major matrices); mat3 uniforms take the
// upper-left 3x3 of a matrix semantic.
std::vector<float> semantic_value(const std::string& semantic, const FrameContext& frame, int components);

}  // namespace fxview::effect
