// A skybox from a cube map (seed 002 ch. 4.1): drawn behind everything, turning with the camera
// but ignoring its translation and zoom.
#pragma once
#include "gl/objects.hpp"
#include "gl/render_target.hpp"
#include "scene/scene.hpp"

namespace fxview::render {

struct SkyboxLook {
    glm::mat3 world_to_cube{1.0f};  // the environment's rotation (scene::Environment::world_to_environment)
    float intensity = 1.0f;
    bool base_level = false;        // the sharp radiance of a prefiltered environment, not screen-size mips
};

class Skybox {
public:
    Skybox();
    // Draws the cube map `cube` into the whole target at the far plane (depth test LEQUAL, no depth write).
    void draw(GLuint cube, const scene::Camera& camera, const gl::RenderTarget& target, const SkyboxLook& look = {});

private:
    gl::Program program_;
    gl::VertexArray vertex_array_;
    gl::Sampler sampler_;
};

}  // namespace fxview::render
