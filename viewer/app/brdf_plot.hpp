// BRDF charts as images (`fxview brdf-plot`), in the manner of BRDF Explorer: the polar plot of the
// plane of incidence, several BRDFs overlaid, linear or logarithmic; and directional albedo
// against the angle of incidence with the line of energy conservation.
#pragma once
#include <string>

#include <vector>

#include "image/image.hpp"

namespace fxview::app {

struct BrdfSeries {
    std::string name;
    std::vector<double> values;  // one per sample: polar, θo from -90° to 90°; albedo, per incidence
};

// A series' values that are NaN or infinite: not drawn, so the legend (and brdf-plot) say how many.
size_t not_finite(const BrdfSeries& s);

struct ChartSize {
    int width = 800, height = 600;
};

// `series` values at θo = -90 + 180 (k + ½) / n degrees (the mirror side left), incidence drawn on the right.
image::FloatImage polar_chart(const std::vector<BrdfSeries>& series, double incidence_degrees, bool logarithmic, ChartSize size);
// `series` values at `incidence_degrees`.
image::FloatImage albedo_chart(const std::vector<BrdfSeries>& series, const std::vector<double>& incidence_degrees, ChartSize size);
// The 3D lobe f(l, ω) (mean of R, G, B) over the hemisphere as a wireframe seen from above and aside;
// `hemisphere` as evaluate_brdf_hemisphere lays it out (φo across, θo up from the bottom row).
image::FloatImage lobe_chart(const image::FloatImage& hemisphere, const std::string& name, double incidence_degrees, ChartSize size);

// Rusinkiewicz's slice (evaluate_brdf_slice) scaled for an 8-bit image: the 99th percentile of the
// green channel becomes white; returns that value (0 when the slice is black, left unscaled).
float scale_slice_for_display(image::FloatImage& slice);
// The margins of slice_chart around the slice (the slice drawn is the chart size less them).
struct SliceMargins {
    int left = 56, top = 48, right = 100, bottom = 46;
};
inline constexpr SliceMargins kSliceMargins{};
// A scaled slice in a chart of `size`: θh and θd axes in degrees, a colour bar from 0 to `white`.
image::FloatImage slice_chart(const image::FloatImage& scaled, float white, double phi_d_degrees, ChartSize size);

}  // namespace fxview::app
