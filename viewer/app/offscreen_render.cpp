#include "app/offscreen_render.hpp"

#include <glad/gl.h>

#include "core/error.hpp"

#include "effect/effect_program.hpp"
#include "effect/parameter_values.hpp"
#include "gl/render_target.hpp"
#include "render/debug_renderer.hpp"
#include "render/effect_renderer.hpp"

namespace fxview::app {

image::FloatImage render_offscreen(const RenderRequest& request) {
    context::ContextOptions context_options;
    context_options.backend = request.backend;
    context_options.window_width = request.width;
    context_options.window_height = request.height;
    context_options.debug_output = request.gl_debug;
    const auto context = context::create_context(context_options);

    gl::RenderTarget target({request.width, request.height, 1, request.samples});
    if (request.effect.path.empty()) {
        render::DebugRenderer renderer;
        renderer.render(request.scene, request.view, target);
    } else {
        const effect::Effect effect = effect::load_effect(request.effect.path, effect_load_options());
        effect::ParameterValues values = effect::default_values(effect);
        for (const auto& assignment : request.effect.sets) effect::set_value_from_text(effect, values, assignment);
        const effect::Technique* technique =
            request.effect.technique.empty() ? &effect.techniques.front() : effect.find_technique(request.effect.technique);
        if (!technique) {
            std::string names;
            for (const auto& t : effect.techniques) names += (names.empty() ? "" : ", ") + t.name;
            throw UsageError(request.effect.path + " has no technique '" + request.effect.technique + "' (it has " + names + ")");
        }
        const effect::CompiledTechnique compiled = effect::compile_technique(effect, *technique);
        render::EffectResources resources(effect, values, texture_folders());
        render::EffectRenderer renderer;
        renderer.render(request.scene, compiled, values, resources, target);
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
