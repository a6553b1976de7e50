// The effect's parameters as ImGui widgets, chosen from their annotations (slider with min/max/step,
// drag, colour picker, checkbox, combo, vector editors), grouped by UIGroup and ordered by UIOrder,
// with units and help text, and a reset per parameter and for all.
#pragma once
#include "render/effect_session.hpp"

namespace fxview::ui {

// Returns true when a value changed this frame.
bool draw_parameter_panel(render::EffectSession& session);

}  // namespace fxview::ui
