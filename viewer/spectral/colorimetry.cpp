#include "spectral/colorimetry.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "spectral/spectral_files.hpp"

namespace fxview::spectral {

Observer load_observer(const std::string& which, const std::string& colord_dir) {
    const std::string file = which == "1931" ? "CIE1931-2deg-XYZ.cmf" : which == "1964" ? "CIE1964-10deg-XYZ.cmf" : "";
    if (file.empty()) throw UsageError("unknown observer '" + which + "' (expected 1931 or 1964)");
    const auto sets = read_cgats(colord_dir + "/cmf/" + file, Extrapolation::Zero);
    if (sets.size() != 3) throw Error(colord_dir + "/cmf/" + file + ": expected 3 data sets (x, y, z)");
    return {which == "1931" ? "CIE1931-2deg" : "CIE1964-10deg", sets[0].spectrum, sets[1].spectrum, sets[2].spectrum};
}

Vec3 spectrum_to_xyz(const Spectrum& s, const Observer& o, const Integration& r) {
    if (r.step < 1 || r.lower > r.upper) throw UsageError("bad integration range " + std::to_string(r.lower) + ".." +
                                                          std::to_string(r.upper) + " step " + std::to_string(r.step));
    double x = 0, y = 0, z = 0, normal = 0;
    for (int nm = r.lower; nm <= r.upper; nm += r.step) {
        const double v = s.at(nm);
        x += v * o.x.at(nm);
        y += v * o.y.at(nm);
        z += v * o.z.at(nm);
        normal += o.y.at(nm);
    }
    // The step size multiplies numerator and k's denominator alike and cancels.
    if (normal <= 0) return {0, 0, 0};
    return {x / normal, y / normal, z / normal};
}

std::array<double, 2> chromaticity(const Vec3& xyz) {
    const double sum = xyz[0] + xyz[1] + xyz[2];
    if (sum <= 0) return {0, 0};
    return {xyz[0] / sum, xyz[1] / sum};
}

Vec3 xyz_to_linear_srgb_unclipped(const Vec3& c) {
    // Eq. 9 (IEC 61966-2-1 / ITU-R BT.709 primaries, D65 white).
    return {3.240479 * c[0] - 1.537150 * c[1] - 0.498535 * c[2],
            -0.969256 * c[0] + 1.875992 * c[1] + 0.041556 * c[2],
            0.055648 * c[0] - 0.204043 * c[1] + 1.057311 * c[2]};
}

Vec3 xyz_to_linear_srgb(const Vec3& xyz, GamutMapping mapping) {
    Vec3 rgb = xyz_to_linear_srgb_unclipped(xyz);
    if (mapping == GamutMapping::Desaturate) {
        // Mix with the grey of equal luminance (Y) until no channel is negative.
        const double grey = std::max(0.0, xyz[1]);
        const double lowest = std::min({rgb[0], rgb[1], rgb[2]});
        if (lowest < 0 && grey > 0) {
            const double t = grey / (grey - lowest);  // fraction of the colour that keeps min >= 0
            for (double& c : rgb) c = grey + t * (c - grey);
        }
    } else if (mapping == GamutMapping::Scale) {
        for (double& c : rgb) c = std::max(c, 0.0);
        const double highest = std::max({rgb[0], rgb[1], rgb[2]});
        if (highest > 1) for (double& c : rgb) c /= highest;
    }
    for (double& c : rgb) c = mapping == GamutMapping::Unbounded ? std::max(c, 0.0) : std::clamp(c, 0.0, 1.0);
    return rgb;
}

double srgb_encode(double linear) {
    const double x = std::clamp(linear, 0.0, 1.0);
    if (x >= 1.0) return 1.0;
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

}  // namespace fxview::spectral
