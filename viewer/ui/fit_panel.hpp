// The BRDF fitter inside the viewer (docs/fitting.md): load a measured grid or MERL file, fit the
// Ashikhmin-Shirley model (seed 000) and show the result on the object through the current effect's
// AshikhminShirleyFit parameters (effects/brdf/analytic.fx), with the error per iteration (fig. 5.2).
// A failed load or fit leaves the parameters as they were and says why.
#pragma once
#include <optional>
#include <string>

#include "fit/ashikhmin_fit.hpp"
#include "render/effect_session.hpp"

namespace fxview::ui {

struct FitPanelState {
    char path[512] = "";
    fit::FitOptions options;
    std::optional<fit::FitResult> result;
    std::string error;
};

// Runs the fit of state.path and, when the session's effect has the fit parameters, applies the
// result and selects AshikhminShirleyFit. Returns false (with state.error set) on failure.
bool run_fit(FitPanelState& state, render::EffectSession* session);

void draw_fit_panel(FitPanelState& state, render::EffectSession* session);

}  // namespace fxview::ui
