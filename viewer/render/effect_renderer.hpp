// Draws a scene with one technique of an effect: pass after pass, each with its own render states
// (reset to the defaults first, as in CgFX), into the frame's target or the effect's render
// targets, drawing every object with its SAS matrices, or one full-screen triangle (Draw = Buffer).
#pragma once
#include <map>
#include <memory>

#include "effect/effect_program.hpp"
#include "gl/render_target.hpp"
#include "render/debug_renderer.hpp"
#include "render/effect_resources.hpp"
#include "render/mesh_cache.hpp"
#include "scene/scene.hpp"

namespace fxview::render {

struct FrameTiming {
    float time = 0.0f;
    int frame = 0;
};

class EffectRenderer {
public:
    void render(const scene::Scene& scene, const effect::CompiledTechnique& technique,
                const effect::ParameterValues& values, EffectResources& resources, const gl::RenderTarget& target,
                FrameTiming timing = {}, bool clear_target = true);
    // Forgets per-pass framebuffers (call when the effect is replaced).
    void reset() { pass_framebuffers_.clear(); }

private:
    struct PassFramebuffer {
        gl::Framebuffer framebuffer;
        gl::Renderbuffer depth;
        std::vector<GLuint> attached;
        int width = 0, height = 0;
    };
    PassFramebuffer& bind_pass_targets(const effect::Pass& pass, const EffectResources& resources);

    MeshCache meshes_;
    gl::VertexArray empty_vertex_array_;  // full-screen passes generate their vertices from gl_VertexID
    std::map<const effect::Pass*, PassFramebuffer> pass_framebuffers_;
    std::unique_ptr<DebugRenderer> scene_renderer_;  // legacy ScriptExternal passes, made on first use
};

}  // namespace fxview::render
