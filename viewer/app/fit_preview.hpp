// The preview of a fit (seed 000 fig. 4.6/4.8): measured, model and difference side by side, each
// the grid unfolded per light angle (rows: θi blocks from 0° down, in each θo from 0°; columns: φo
// from 0° to 180° and mirrored back to 360°, the full hemisphere of an isotropic BRDF).
#pragma once
#include "fit/brdf_grid.hpp"
#include "image/image.hpp"

namespace fxview::app {

struct PreviewOptions {
    double brighten = 3.0;  // the thesis' ×3 (values are multiplied before display)
    double gamma = 1.0;     // or its gamma 2.2 (values^(1/gamma)); 1 keeps the plain scale
};

// Linear RGB image of width 3 × 2·phi_out, height theta_in × theta_out; the third panel is |measured − model|.
image::FloatImage fit_preview(const fit::BrdfGrid& measured, const fit::BrdfGrid& model, const PreviewOptions& options);

}  // namespace fxview::app
