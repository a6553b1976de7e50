#include "app/brdf_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace fxview::app {

double grid_incidence_degrees(int tile) { return 1.0 + 2.0 * tile; }

BrdfCheck analyse_brdf_grid(const image::FloatImage& forward, const image::FloatImage& swapped) {
    if (forward.width != kGridWidth || forward.height != kGridHeight || swapped.width != kGridWidth || swapped.height != kGridHeight)
        throw Error("brdf-check: the grid images have the wrong size");
    BrdfCheck check;
    const double solid_angle = (1.0 / kGridTile) * (2.0 * std::numbers::pi / kGridTile);  // dμ dφ, equal for every pixel
    // GL's row 0 is the image's last row.
    const auto at = [&](const image::FloatImage& image, int x, int gl_y) { return image.pixel(x, kGridHeight - 1 - gl_y); };
    double peak = 0;
    for (int y = 0; y < kGridHeight; ++y)
        for (int x = 0; x < kGridWidth; ++x)
            for (int c = 0; c < 3; ++c)
                for (const image::FloatImage* image : {&forward, &swapped}) {
                    const double f = image->pixel(x, y)[c];
                    if (std::isfinite(f)) peak = std::max(peak, std::abs(f));
                }
    for (int tile = 0; tile < kGridIncidences; ++tile) {
        const int x0 = (tile % kGridTilesX) * kGridTile, y0 = (tile / kGridTilesX) * kGridTile;
        std::array<double, 3> albedo{};
        for (int b = 0; b < kGridTile; ++b) {
            const double mu = (b + 0.5) / kGridTile;
            for (int a = 0; a < kGridTile; ++a) {
                const float* f = at(forward, x0 + a, y0 + b);
                const float* g = at(swapped, x0 + a, y0 + b);
                ++check.samples;
                bool finite = true;
                for (int c = 0; c < 3; ++c) finite = finite && std::isfinite(f[c]) && std::isfinite(g[c]);
                if (!finite) {
                    ++check.non_finite;
                    continue;
                }
                if (std::min({f[0], f[1], f[2], g[0], g[1], g[2]}) < 0.0f) ++check.negative;
                for (int c = 0; c < 3; ++c) {
                    albedo[static_cast<size_t>(c)] += f[c] * mu * solid_angle;
                    const double larger = std::max(std::abs(f[c]), std::abs(g[c]));
                    if (larger <= 1e-6 * peak) continue;
                    const double relative = std::abs(f[c] - g[c]) / larger;
                    if (relative > check.reciprocity) {
                        check.reciprocity = relative;
                        check.reciprocity_incidence = grid_incidence_degrees(tile);
                        check.reciprocity_exitance = std::acos(mu) * 180.0 / std::numbers::pi;
                        check.reciprocity_azimuth = 360.0 * (a + 0.5) / kGridTile;
                    }
                }
            }
        }
        check.incidence_degrees.push_back(grid_incidence_degrees(tile));
        check.albedo.push_back(albedo);
        const double largest = std::max({albedo[0], albedo[1], albedo[2]});
        if (largest > check.max_albedo) {
            check.max_albedo = largest;
            check.max_albedo_degrees = grid_incidence_degrees(tile);
        }
    }
    check.conserves_energy = check.max_albedo <= 1.0 + BrdfCheck::kEnergyTolerance;
    check.reciprocal = check.reciprocity <= BrdfCheck::kReciprocityTolerance;
    return check;
}

}  // namespace fxview::app
