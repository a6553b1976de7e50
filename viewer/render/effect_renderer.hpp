// Draws a scene with one technique of an effect: pass after pass, each with its own render states
// (reset to the defaults first, as in CgFX), every object with its SAS matrices.
#pragma once
#include "effect/effect_program.hpp"
#include "gl/render_target.hpp"
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
                const effect::ParameterValues& values, const gl::RenderTarget& target, FrameTiming timing = {});

private:
    MeshCache meshes_;
};

}  // namespace fxview::render
