// The effect's parameters as ImGui widgets, chosen from their annotations (slider with min/max/step,
// drag, colour picker, checkbox, combo, vector editors), grouped by UIGroup and ordered by UIOrder,
// with units and help text, and a reset per parameter and for all.
#pragma once
#include <string>
#include <vector>

#include "render/effect_session.hpp"

namespace fxview::ui {

// Shows first the parameters that the `techniques` on screen read (their programs' active uniforms)
// or that a plugin names; the rest under a closed "Not read by ..." fold. Returns true when a value
// changed this frame.
bool draw_parameter_panel(render::EffectSession& session, const std::vector<std::string>& techniques);

}  // namespace fxview::ui
