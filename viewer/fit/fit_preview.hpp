// The preview of a fit (seed 000 fig. 4.6/4.8): measured, model and their signed difference side by
// side, each the grid unfolded per light angle (rows: θi blocks from 0° down, separated by a grey
// line, in each θo from 0°; columns: φo from −180° to 180° with φo = 0°, the mirror side, in the
// centre — the full hemisphere of an isotropic BRDF). Rows outside the fit's limit angle are greyed.
#pragma once
#include "fit/brdf_grid.hpp"
#include "image/image.hpp"

namespace fxview::fit {

struct PreviewOptions {
    double brighten = 3.0;    // the thesis' ×3 (values are multiplied before display)
    double gamma = 1.0;       // or its gamma 2.2 (values^(1/gamma)); 1 keeps the plain scale
    double limit_deg = 90.0;  // rows with θi or θo beyond it were not fitted: drawn greyed
};

struct FitPreview {
    image::FloatImage image;        // linear RGB with alpha 1 everywhere
    double difference_scale = 0.0;  // the |measured − model| (mean of RGB) drawn at full colour
};

// Width 3 panels of 2·phi_out − 1 columns plus two separators; height theta_in × theta_out rows plus
// one line between θi blocks and a legend strip under the difference panel. The difference panel is
// false colour: red where the measurement is above the model, blue where it is below, black where
// they agree, full colour at ±difference_scale (the largest difference inside the fit).
FitPreview fit_preview(const BrdfGrid& measured, const BrdfGrid& model, const PreviewOptions& options);

}  // namespace fxview::fit
