#include "render/effect_renderer.hpp"

#include "effect/render_states.hpp"

namespace fxview::render {

void EffectRenderer::render(const scene::Scene& scene, const effect::CompiledTechnique& technique,
                            const effect::ParameterValues& values, const gl::RenderTarget& target, FrameTiming timing) {
    target.bind_for_drawing();
    effect::FrameContext frame;
    const float aspect = static_cast<float>(target.width()) / static_cast<float>(target.height());
    frame.view = math::view_matrix(scene.camera.pose);
    frame.projection =
        math::perspective_matrix(scene.camera.fov_y_degrees, aspect, scene.camera.near_plane, scene.camera.far_plane);
    frame.camera_position = math::camera_world_position(scene.camera.pose);
    frame.light_position = scene.light.world_position();
    frame.viewport_size = {static_cast<float>(target.width()), static_cast<float>(target.height())};
    frame.time = timing.time;
    frame.frame = timing.frame;

    for (size_t p = 0; p < technique.passes.size(); ++p) {
        const effect::CompiledPass& pass = technique.passes[p];
        const effect::RenderStates& states = pass.pass->states;
        effect::apply_render_states(states);
        if (p == 0 || states.clear) {
            // Clearing must reach every channel and the depth buffer whatever the pass's masks say.
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glDepthMask(GL_TRUE);
            const auto color = states.clear_color.value_or(
                std::array<float, 4>{scene.background.r, scene.background.g, scene.background.b, scene.background.a});
            glClearColor(color[0], color[1], color[2], color[3]);
            glClearDepth(states.clear_depth.value_or(1.0f));
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            effect::apply_render_states(states);
        }
        glUseProgram(pass.program.get());
        for (const auto& object : scene.objects) {
            frame.world = math::world_matrix(object.pose, object.scale);
            effect::bind_uniforms(pass, values, frame);
            meshes_.get(object.mesh).draw();
        }
    }
    glUseProgram(0);
    effect::apply_render_states({});
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    target.resolve();
}

}  // namespace fxview::render
