#include "app/offscreen_render.hpp"

#include <glad/gl.h>

#include "core/error.hpp"

#include <iostream>

#include "effect/preset.hpp"
#include "gl/render_target.hpp"
#include "render/debug_renderer.hpp"
#include "render/effect_session.hpp"
#include "render/environment_maps.hpp"
#include "render/skybox.hpp"

namespace fxview::app {

image::FloatImage render_offscreen(const RenderRequest& request) {
    context::ContextOptions context_options;
    context_options.backend = request.backend;
    context_options.window_width = request.width;
    context_options.window_height = request.height;
    context_options.debug_output = request.gl_debug;
    const auto context = context::create_context(context_options);

    gl::RenderTarget target({request.width, request.height, 1, request.samples});
    const auto draw_environment = [&](const render::EnvironmentMaps& environment) {  // behind the objects
        render::Skybox().draw(environment.background().texture.get(), request.scene.camera, target,
                              {request.scene.environment.world_to_environment(), request.scene.environment.intensity, true});
        target.resolve();
    };
    if (request.effect.path.empty()) {
        render::DebugRenderer renderer;
        renderer.render(request.scene, request.view, target);
        // Without an effect the environment is only the background, but it is loaded and shown all the
        // same: a missing file is an error, never silently ignored.
        if (!request.scene.environment.source.empty())
            draw_environment(render::EnvironmentMaps(request.scene.environment.source, resource_limits(request.effect.access)));
    } else {
        const auto session = open_effect_session(request.effect);
        if (!request.effect.save_preset.empty())
            effect::save_preset(request.effect.save_preset, session->effect(), session->technique(), session->values());
        session->render(request.scene, target);
        for (const std::string& warning : session->scene_warnings(request.scene))  // after it: some need the loaded environment
            std::cerr << warning << "\n";
        if (!request.scene.environment.source.empty()) draw_environment(session->environment(request.scene.environment));
    }
    image::FloatImage image = target.read_color(0);

    if (context->window()) {
        glBlitNamedFramebuffer(target.framebuffer(), 0, 0, 0, request.width, request.height, 0, 0, request.width,
                               request.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        context->swap_buffers();
    }
    return image;
}

}  // namespace fxview::app
