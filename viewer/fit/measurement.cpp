#include "fit/measurement.hpp"

#include "core/text.hpp"

namespace fxview::fit {

BrdfGrid read_measurement(const std::string& path, const ResourceLimits& limits) {
    if (lower_extension(path) == ".binary") return merl_to_grid(read_merl(path, limits), thesis_grid());
    return read_brdf_grid(path, limits);
}

Measurement read_measurement_for_fit(const std::string& path, const ResourceLimits& limits) {
    if (lower_extension(path) != ".binary") return {read_brdf_grid(path, limits), std::nullopt};
    Measurement m;
    m.merl = read_merl(path, limits);
    m.grid = merl_to_grid(*m.merl, thesis_grid());
    return m;
}

Observations observations(const Measurement& measurement, double limit_deg) {
    return measurement.merl ? observations(*measurement.merl, limit_deg) : observations(measurement.grid, limit_deg);
}

}  // namespace fxview::fit
