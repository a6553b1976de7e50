#include "render/effect_renderer.hpp"

#include <optional>
#include <set>

#include "effect/render_states.hpp"

namespace fxview::render {

namespace {

// Whether the parameters of the loops a pass sits in (legacy LoopByCount) reach its iteration.
bool runs(const effect::Pass& pass, const effect::ParameterValues& values) {
    for (const effect::LoopCondition& condition : pass.runs_if) {
        const auto value = values.numbers.find(condition.parameter);
        if (value != values.numbers.end() && !value->second.empty() && value->second[0] < condition.iteration) return false;
    }
    return true;
}

// Clears the bound framebuffer to the states' ClearSetColor / ClearSetDepth (else the scene's
// background and depth 1), every channel whatever the pass's masks say.
void clear_bound_target(const effect::RenderStates& states, const scene::Scene& scene) {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    const auto color = states.clear_color.value_or(std::array<float, 4>{scene.background.r, scene.background.g, scene.background.b, scene.background.a});
    glClearColor(color[0], color[1], color[2], color[3]);
    glClearDepth(states.clear_depth.value_or(1.0f));
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace

EffectRenderer::PassFramebuffer& EffectRenderer::bind_pass_targets(const effect::Pass& pass,
                                                                   const EffectResources& resources) {
    std::vector<GLuint> textures;
    int width = 0, height = 0;
    for (const auto& name : pass.states.render_targets) {
        const GpuTexture* target = resources.find(name);
        if (!target) throw effect::EffectError(pass.where, "render target " + name + " was not created");
        if (!textures.empty() && (target->width != width || target->height != height))
            throw effect::EffectError(pass.where, "pass " + pass.name + " renders into targets of different sizes");
        width = target->width;
        height = target->height;
        textures.push_back(target->texture.get());
    }
    PassFramebuffer& entry = pass_framebuffers_[&pass];
    if (entry.attached != textures || entry.width != width || entry.height != height) {
        entry.framebuffer = gl::create_framebuffer();
        entry.depth = gl::create_renderbuffer();
        glNamedRenderbufferStorage(entry.depth.get(), GL_DEPTH_COMPONENT32F, width, height);
        std::vector<GLenum> buffers;
        for (size_t i = 0; i < textures.size(); ++i) {
            glNamedFramebufferTexture(entry.framebuffer.get(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i), textures[i], 0);
            buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
        }
        glNamedFramebufferRenderbuffer(entry.framebuffer.get(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, entry.depth.get());
        glNamedFramebufferDrawBuffers(entry.framebuffer.get(), static_cast<GLsizei>(buffers.size()), buffers.data());
        if (glCheckNamedFramebufferStatus(entry.framebuffer.get(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw effect::EffectError(pass.where, "pass " + pass.name + ": its render targets do not form a complete framebuffer");
        entry.attached = textures;
        entry.width = width;
        entry.height = height;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, entry.framebuffer.get());
    glViewport(0, 0, width, height);
    return entry;
}

void EffectRenderer::render(const scene::Scene& scene, const effect::CompiledTechnique& technique,
                            const effect::ParameterValues& values, EffectResources& resources,
                            const gl::RenderTarget& target, FrameTiming timing, bool clear_target) {
    resources.fit_render_targets(target.width(), target.height());
    if (!empty_vertex_array_) empty_vertex_array_ = gl::create_vertex_array();
    effect::FrameContext frame;
    const float aspect = static_cast<float>(target.width()) / static_cast<float>(target.height());
    frame.view = math::view_matrix(scene.camera.pose);
    frame.projection =
        math::perspective_matrix(scene.camera.fov_y_degrees, aspect, scene.camera.near_plane, scene.camera.far_plane);
    frame.camera_position = math::camera_world_position(scene.camera.pose);
    frame.light_position = scene.light.world_position();
    const scene::LightGeometry light = scene::light_geometry(scene.light);
    frame.light_radius = static_cast<float>(light.equivalent_radius());
    frame.light_shape = static_cast<float>(light.is_flat() ? static_cast<int>(light.shape) : 0);
    frame.light_half_size = glm::vec2(light.half_size);
    frame.light_frame = glm::mat3(glm::vec3(light.u), glm::vec3(light.v), glm::vec3(light.normal));
    frame.light_radiance = static_cast<float>(light.radiance);
    frame.environment_rotation = scene.environment.world_to_environment();
    frame.environment_intensity = scene.environment.source.empty() ? 0.0f : scene.environment.intensity;
    frame.time = timing.time;
    frame.frame = timing.frame;

    std::set<const void*> cleared;  // targets cleared this frame: each is cleared before its first pass
    if (!clear_target) cleared.insert(&target);  // the caller draws several objects into one frame
    // A clear from before a loop whose copies the loop's value skips: the next pass that runs does it.
    std::optional<effect::RenderStates> carried_clear;
    for (const effect::CompiledPass& pass : technique.passes) {
        const effect::RenderStates& states = pass.pass->states;
        if (!runs(*pass.pass, values)) {  // a copy of a loop's passes beyond the loop parameter's current value
            if (states.clear && pass.pass->carries_clear && !carried_clear) carried_clear = states;
            continue;
        }
        const void* destination = &target;
        if (states.render_targets.empty()) {
            target.bind_for_drawing();
            frame.viewport_size = {static_cast<float>(target.width()), static_cast<float>(target.height())};
        } else {
            const PassFramebuffer& framebuffer = bind_pass_targets(*pass.pass, resources);
            destination = &framebuffer;
            frame.viewport_size = {static_cast<float>(framebuffer.width), static_cast<float>(framebuffer.height)};
        }
        const bool first_use = cleared.insert(destination).second;
        if (first_use || states.clear || carried_clear) {
            const effect::RenderStates& clear = states.clear || !carried_clear ? states : *carried_clear;
            clear_bound_target(clear, scene);
        }
        carried_clear.reset();
        effect::apply_render_states(states);
        if (states.draw_scene) {
            if (!scene_renderer_) scene_renderer_ = std::make_unique<DebugRenderer>();
            scene_renderer_->draw_objects(scene, DebugView::Plain, frame.viewport_size.x / frame.viewport_size.y);
            continue;
        }
        glVertexAttrib4f(5, 1.0f, 1.0f, 1.0f, 1.0f);  // legacy COLOR0 inputs: meshes carry no colours, white
        glUseProgram(pass.program->get());
        for (const auto& uniform : pass.uniforms) {
            if (uniform.texture_unit < 0) continue;
            const effect::Parameter& sampler = *uniform.parameter;
            const GpuTexture* texture = resources.acquire(sampler.texture);
            if (!texture)
                throw effect::EffectError(sampler.where, "sampler " + sampler.name +
                                                             " has no texture (give it a ResourceName, a sampler_state "
                                                             "Texture, or --set " + sampler.name + "=FILE)");
            glBindTextureUnit(static_cast<GLuint>(uniform.texture_unit), texture->texture.get());
            glBindSampler(static_cast<GLuint>(uniform.texture_unit), resources.sampler(sampler.sampler));
        }
        if (states.draw_buffer && resources.effect().legacy) {
            // Legacy quad shaders read POSITION and TEXCOORD0 of a screen-filling quad: the plane
            // spans [-1,1]^2 with uv 0..1 (v up, as render targets are stored).
            frame.world = glm::mat4(1.0f);
            effect::bind_uniforms(pass, values, frame);
            meshes_.get("plane").draw();
        } else if (states.draw_buffer) {
            frame.world = glm::mat4(1.0f);
            effect::bind_uniforms(pass, values, frame);
            glBindVertexArray(empty_vertex_array_.get());
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glBindVertexArray(0);
        } else {
            for (const auto& object : scene.objects) {
                frame.world = math::world_matrix(object.pose, object.scale);
                effect::bind_uniforms(pass, values, frame);
                meshes_.get(object.mesh).draw();
            }
        }
        for (const auto& uniform : pass.uniforms)
            if (uniform.texture_unit >= 0) glBindSampler(static_cast<GLuint>(uniform.texture_unit), 0);
    }
    glUseProgram(0);
    if (cleared.insert(&target).second) {  // no pass ran into the frame (a loop of 0): it shows the background
        target.bind_for_drawing();
        clear_bound_target(carried_clear.value_or(effect::RenderStates{}), scene);
    }
    effect::apply_render_states({});
    target.resolve();
}

}  // namespace fxview::render
