// The BRDF fitter inside the viewer (docs/fitting.md): load a measured grid or MERL file, fit the
// Ashikhmin-Shirley model (seed 000) and show the result on the object through the current effect's
// AshikhminShirleyFit parameters (effects/brdf/analytic.fx, effects/brdf/measured.fx), with the error
// per iteration (fig. 5.2) and the measured | model | difference preview of the thesis (fig. 4.6/4.8).
// A failed load or fit leaves the parameters as they were and says why.
#pragma once
#include <optional>
#include <string>

#include "fit/ashikhmin_fit.hpp"
#include "gl/objects.hpp"
#include "render/effect_session.hpp"

namespace fxview::ui {

struct FitPanelState {
    char path[512] = "";
    fit::FitOptions options;
    std::optional<fit::FitResult> result;
    std::string error;
    gl::Texture preview;  // measured | model | difference (seed 000 fig. 4.6/4.8), sRGB-encoded
    int preview_width = 0, preview_height = 0;
    float preview_brighten = 3.0f;
    double preview_difference_scale = 0.0;  // |measured - model| at full colour in the difference panel
};

// Runs the fit of state.path and, when the session's effect has the fit parameters, applies the
// result and selects AshikhminShirleyFit. Returns false (with state.error set) on failure.
bool run_fit(FitPanelState& state, render::EffectSession* session);

void draw_fit_panel(FitPanelState& state, render::EffectSession* session);

}  // namespace fxview::ui
