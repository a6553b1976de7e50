// What is rendered: a camera, one light and objects, each placed independently (seed 002 ch. 4.1).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "math/transform.hpp"
#include "scene/light_geometry.hpp"
#include "scene/light_intensity.hpp"

namespace fxview::scene {

struct Camera {
    math::CameraPose pose;
    float fov_y_degrees = 45.0f;
    float near_plane = 0.05f;
    float far_plane = 100.0f;
};

// A light: a point, a sphere of `radius` (seen as a disc of angular radius asin(radius / distance)),
// or a flat disc or rectangle facing the origin (a ceiling panel, a window; scene/light_geometry.hpp);
// `pose.rotation` turns its position about the origin (the light is orbited). A sphere gives the
// irradiance of the point light at its centre, so its radius changes reflections (highlights,
// diffraction orders), not the diffuse shading; a flat light emits a uniform radiance that gives the
// point light's irradiance at the origin. Effects read them through the LIGHTRADIUS and LIGHTSHAPE semantics.
struct Light {
    math::Pose pose{glm::vec3(2.0f, 2.0f, 3.0f), glm::quat(1.0f, 0.0f, 0.0f, 0.0f)};
    // In photometric units (scene/light_intensity.hpp); empty: each effect's own light strength.
    std::optional<LightIntensity> intensity;
    LightShape shape = LightShape::Sphere;
    float radius = 0.0f;       // world units, a sphere's or a disc's; 0: a point light
    glm::vec2 size{1.0f};      // a rectangle's width and height, world units
    // A spectral-library name: the light's spectrum in every spectral effect (each parameter annotated
    // SceneLight = "spectrum" follows it); empty: each effect's own choice.
    std::string spectrum;

    glm::vec3 world_position() const { return glm::mat3_cast(pose.rotation) * pose.position; }
    // Whether it is more than a point.
    bool has_size() const { return shape == LightShape::Rectangle ? size.x > 0 && size.y > 0 : radius > 0; }
};

struct SceneObject {
    std::string mesh = "sphere";  // built-in name or OBJ path
    math::Pose pose;
    glm::vec3 scale{1.0f};
};

// The environment around the scene: its radiance lights effects that use image-based lighting
// (effects/lib/environment.glsl) and is drawn as the background. `source` as lighting/environment_sources.hpp
// names it ("studio", "sky:35,5500", "furnace", a file); empty: none (black, lights nothing).
struct Environment {
    std::string source;
    float rotation_degrees = 0.0f;  // about the vertical (+Y) axis
    float intensity = 1.0f;         // scales its radiance
    // World direction -> the environment's own frame (the inverse of its rotation).
    glm::mat3 world_to_environment() const;
};

struct Scene {
    Camera camera;
    Light light;
    Environment environment;
    std::vector<SceneObject> objects{SceneObject{}};
    glm::vec4 background{0.0f, 0.0f, 0.0f, 0.0f};
};

}  // namespace fxview::scene
