// `fxview brdf-check`: physics checks of any BRDF an effect renders over a direction grid (the
// BrdfGrid technique of effects/lib/brdf_file.glsl, which every .brdf file gets): directional
// albedo against θi by quadrature (a BRDF that reflects more than it receives is flagged, with the θi
// where it does), reciprocity (the largest relative |f(L,V) − f(V,L)|), negative and non-finite values.
#pragma once
#include <array>
#include <vector>

#include "image/image.hpp"

namespace fxview::app {

// The grid's layout, as the GLSL lays it out.
constexpr int kGridTile = 256, kGridTilesX = 9, kGridIncidences = 45;
constexpr int kGridWidth = kGridTile * kGridTilesX, kGridHeight = kGridTile * ((kGridIncidences + kGridTilesX - 1) / kGridTilesX);
double grid_incidence_degrees(int tile);  // θi of tile t: 1° + 2° t

struct BrdfCheck {
    std::vector<double> incidence_degrees;
    std::vector<std::array<double, 3>> albedo;  // per incidence, RGB
    double max_albedo = 0, max_albedo_degrees = 0;
    // The quadrature's own error is below 1e-3 for smooth lobes; a BRDF sharper than the grid (a
    // lobe narrower than ~1°) can be misjudged either way.
    static constexpr double kEnergyTolerance = 0.01;
    bool conserves_energy = true;
    double reciprocity = 0;  // largest |f(L,V) − f(V,L)| / max(|f|), where f is above 1e-6 of its peak
    // Float rounding at grazing angles reaches ~1e-4 for reciprocal models; a real asymmetry is of order 1.
    static constexpr double kReciprocityTolerance = 1e-3;
    bool reciprocal = true;
    double reciprocity_incidence = 0, reciprocity_exitance = 0, reciprocity_azimuth = 0;  // degrees, where
    long negative = 0, non_finite = 0, samples = 0;
};

// `forward` holds f(L, V), `swapped` f(V, L), both as rendered (rows from the top).
BrdfCheck analyse_brdf_grid(const image::FloatImage& forward, const image::FloatImage& swapped);

}  // namespace fxview::app
