// Reading a measured BRDF from either format fxview knows: a grid CSV (brdf_grid.hpp) or a MERL
// .binary file (merl.hpp), the latter sampled on the thesis' grid.
#pragma once
#include <string>

#include "fit/brdf_grid.hpp"

namespace fxview::fit {

BrdfGrid read_measurement(const std::string& path, const ResourceLimits& limits = {});

}  // namespace fxview::fit
