#include "fit/measurement.hpp"

#include "core/text.hpp"
#include "fit/merl.hpp"

namespace fxview::fit {

BrdfGrid read_measurement(const std::string& path) {
    if (lower_extension(path) == ".binary") return merl_to_grid(read_merl(path), thesis_grid());
    return read_brdf_grid(path);
}

}  // namespace fxview::fit
