#include "spectral/level_of_detail.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fxview::spectral {

int lod_spacing(int level) {
    if (level < 1 || level > kLodLevels) throw UsageError("LOD level must be 1..9, not " + std::to_string(level));
    return 1 << (kLodLevels - level);
}

double lod_interpolated(const std::function<double(int)>& f, int nm, int lower, int upper, int spacing) {
    const int below = lower + (nm - lower) / spacing * spacing;
    const int above = std::min(below + spacing, upper);
    if (above == below) return f(below);
    const double t = static_cast<double>(nm - below) / (above - below);
    return f(below) * (1.0 - t) + f(above) * t;
}

Vec3 spectrum_to_xyz_lod(const Spectrum& spectrum, const Observer& observer, int lower, int upper, int spacing) {
    Vec3 xyz{0, 0, 0};
    double ybar_sum = 0;
    const Spectrum* cmf[3] = {&observer.x, &observer.y, &observer.z};
    const auto lerp = [&](const Spectrum& s, int nm) { return lod_interpolated([&](int at) { return s.at(at); }, nm, lower, upper, spacing); };
    for (int nm = lower; nm <= upper; ++nm) {
        const double value = lerp(spectrum, nm);
        for (int c = 0; c < 3; ++c) xyz[c] += value * lerp(*cmf[c], nm);
        ybar_sum += lerp(observer.y, nm);
    }
    for (double& v : xyz) v /= ybar_sum;
    return xyz;
}

Vec3 xyz_to_lab(const Vec3& xyz, const Vec3& white) {
    const auto f = [](double t) {
        constexpr double delta = 6.0 / 29.0;
        return t > delta * delta * delta ? std::cbrt(t) : t / (3 * delta * delta) + 4.0 / 29.0;
    };
    const double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double delta_e_ab(const Vec3& a, const Vec3& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace fxview::spectral
