// The render states a pass may set (CgFX names, case-insensitive). Every pass starts from the
// defaults below, as in CgFX: states do not leak from one pass into the next.
#pragma once
#include <glad/gl.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "effect/source_map.hpp"

namespace fxview::effect {

struct RenderStates {
    bool depth_test = true;
    bool depth_write = true;
    GLenum depth_func = GL_LESS;
    bool cull = false;
    GLenum cull_face = GL_BACK;
    bool blend = false;
    GLenum blend_src = GL_ONE, blend_dst = GL_ZERO;
    GLenum blend_equation = GL_FUNC_ADD;
    std::array<bool, 4> color_mask{true, true, true, true};
    GLenum polygon_mode = GL_FILL;
    bool clear = false;  // clear the target before the pass (the first pass always clears)
    std::optional<std::array<float, 4>> clear_color;
    std::optional<float> clear_depth;
    std::vector<std::string> render_targets;  // colour attachments by index; empty: the frame's target
    bool draw_buffer = false;  // Draw = Buffer: one full-screen triangle instead of the scene's objects
    // Legacy SAS scripts' ScriptExternal: the scene's objects drawn by fxview's plain shader (what
    // FX Composer's other materials drew), not by the pass's programs.
    bool draw_scene = false;
};

// The right-hand side of `State = value;`: words and numbers in order, e.g. (SrcAlpha, OneMinusSrcAlpha).
struct StateValue {
    std::vector<std::string> words;
    std::vector<double> numbers;
    std::vector<bool> is_number;  // per element, in order
};

// Sets one state; throws EffectError at `where` for an unknown state or a bad value.
void set_render_state(RenderStates& states, const std::string& name, const StateValue& value,
                      const SourceLocation& where);

void apply_render_states(const RenderStates& states);

}  // namespace fxview::effect
