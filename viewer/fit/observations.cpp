// The samples a fit sees: a grid's or a MERL table's measurements with their weights (the solid
// angles of eq. 4.25), what lies outside the limit angle or the domain counted apart.
#include <cmath>
#include <numbers>

#include "fit/brdf_fit.hpp"

namespace fxview::fit {
namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

Observations observations(const BrdfGrid& grid, double limit_deg) {
    const std::vector<double> w = solid_angle_weights(grid, limit_deg);
    double sum = 0;
    for (double x : w) sum += x;
    Observations data;
    data.total = grid.size();
    for (size_t i = 0; i < grid.theta_in.size(); ++i) {
        const glm::dvec3 l = grid.light(i);
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p) {
                const double weight = w[o * grid.phi_out.size() + p];
                // Light or camera at the horizon: weight cos θi = 0, and the lobe's max(n·l, n·v) may be 0
                // too (0 · ∞); a camera at θo = 90° sees 1/(n·v) terms of 1e32 (`--limit 90` let them
                // dominate the fit).
                if (grid.theta_in[i] > limit_deg || l.z < 1e-9 || grid.camera(o, p).z < 1e-9 || weight <= 0) {
                    ++data.outside_limit;
                    continue;
                }
                const std::array<double, 3>& value = grid.values[grid.index(i, o, p)];
                if (value[0] < 0 || value[1] < 0 || value[2] < 0) {  // as in MERL files: not a measurement, left out and counted
                    ++data.masked;
                    continue;
                }
                data.samples.push_back({l, grid.camera(o, p), weight * l.z / sum, value});
            }
    }
    return data;
}

Observations observations(const MerlBrdf& merl, double limit_deg) {
    // Every bin at its centre: θh = ((h + ½)/90)² · 90° (the table's square-root index), θd and φd
    // linear, φh = 0 (isotropic). Its measure in (ωi, ωo) is 4 cos θd sin θh sin θd dθh dθd dφd
    // (Rusinkiewicz's Jacobian, dφh integrated); times cos θi as in eq. 4.25.
    const double limit_cos = std::cos(limit_deg * kPi / 180.0) - 1e-12;
    Observations data;
    data.total = static_cast<size_t>(kMerlThetaH) * kMerlThetaD * kMerlPhiD;
    data.samples.reserve(data.total);
    double sum = 0;
    for (int h = 0; h < kMerlThetaH; ++h) {
        const double d_theta_h = (2.0 * h + 1.0) / (kMerlThetaH * kMerlThetaH) * kPi / 2;
        for (int d = 0; d < kMerlThetaD; ++d)
            for (int p = 0; p < kMerlPhiD; ++p) {
                const BinDirections b = merl_bin_centre(h, d, p);
                const std::array<double, 3> value = merl.bin(h, d, p);
                // Bins below the horizon hold the database's negative "no data" marker in every valid
                // file: outside the domain, not gaps worth a warning. Only negative bins above it are.
                if (b.l.z < limit_cos || b.v.z < limit_cos || b.l.z < 1e-9 || b.v.z < 1e-9) {
                    ++data.outside_limit;
                    continue;
                }
                if (value[0] < 0 || value[1] < 0 || value[2] < 0) {
                    ++data.masked;
                    continue;
                }
                const double measure = 4.0 * std::cos(b.theta_diff) * std::sin(b.theta_half) * std::sin(b.theta_diff) * d_theta_h *
                                       (kPi / 2 / kMerlThetaD) * (kPi / kMerlPhiD);
                sum += measure * b.l.z;
                data.samples.push_back({b.l, b.v, measure * b.l.z, value});
            }
    }
    // The weights sum to 1: a cost does not grow with the number of bins.
    for (Observation& o : data.samples) o.weight /= sum;
    return data;
}

}  // namespace fxview::fit
