// Reading a measured BRDF from either format fxview knows: a grid CSV (brdf_grid.hpp) or a MERL
// .binary file (merl.hpp).
#pragma once
#include <optional>
#include <string>

#include "fit/brdf_fit.hpp"
#include "fit/brdf_grid.hpp"
#include "fit/merl.hpp"

namespace fxview::fit {

// The data on a grid: a MERL file sampled on the thesis' grid (for previews and textures).
BrdfGrid read_measurement(const std::string& path, const ResourceLimits& limits = {});

// For fitting: the grid (previews) and, for a MERL file, its full table, which is what is fitted.
struct Measurement {
    BrdfGrid grid;
    std::optional<MerlBrdf> merl;
};
Measurement read_measurement_for_fit(const std::string& path, const ResourceLimits& limits = {});
// What a fit uses: every valid MERL bin, or the grid's samples.
Observations observations(const Measurement& measurement, double limit_deg);

}  // namespace fxview::fit
