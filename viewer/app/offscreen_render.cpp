#include "app/offscreen_render.hpp"

#include <glad/gl.h>

#include "gl/render_target.hpp"
#include "render/debug_renderer.hpp"

namespace fxview::app {

image::FloatImage render_offscreen(const RenderRequest& request) {
    context::ContextOptions context_options;
    context_options.backend = request.backend;
    context_options.window_width = request.width;
    context_options.window_height = request.height;
    context_options.debug_output = request.gl_debug;
    const auto context = context::create_context(context_options);

    gl::RenderTarget target({request.width, request.height, 1, request.samples});
    render::DebugRenderer renderer;
    renderer.render(request.scene, request.view, target);
    image::FloatImage image = target.read_color(0);

    if (context->window()) {
        glBlitNamedFramebuffer(target.framebuffer(), 0, 0, 0, request.width, request.height, 0, 0, request.width,
                               request.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        context->swap_buffers();
    }
    return image;
}

}  // namespace fxview::app
