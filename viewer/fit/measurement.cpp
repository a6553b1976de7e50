#include "fit/measurement.hpp"

#include "core/text.hpp"
#include "fit/merl.hpp"

namespace fxview::fit {

BrdfGrid read_measurement(const std::string& path, const ResourceLimits& limits) {
    if (lower_extension(path) == ".binary") return merl_to_grid(read_merl(path, limits), thesis_grid());
    return read_brdf_grid(path, limits);
}

}  // namespace fxview::fit
