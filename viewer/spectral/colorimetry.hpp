// Colorimetry of seed 002 (DOMAIN.md §2): tristimulus integration with the observer's colour
// matching functions, chromaticity, XYZ to linear sRGB (eq. 9) with gamut handling, sRGB encoding.
#pragma once
#include <array>
#include <string>

#include "spectral/spectrum.hpp"

namespace fxview::spectral {

struct Observer {
    std::string name;  // "CIE1931-2deg" or "CIE1964-10deg"
    Spectrum x, y, z;  // zero outside the tabulated 360..830 nm
};

// Reads an observer from colord-data's CMF files (5 nm, 360-830), resampled linearly to 1 nm.
// `which` is "1931" or "1964"; `colord_dir` defaults to /usr/share/colord.
Observer load_observer(const std::string& which, const std::string& colord_dir = "/usr/share/colord");

using Vec3 = std::array<double, 3>;

struct Integration {
    int lower = 360;  // nm, inclusive
    int upper = 830;  // nm, inclusive
    int step = 1;     // nm between samples (the thesis' `steps`, the simplest level of detail)
};

// XYZ = k * sum I(l) cmf(l) dl over lower, lower+step, ..., upper, with k = 1 / sum ybar(l) dl over
// the same samples: a constant spectrum of 1 gives Y = 1.
Vec3 spectrum_to_xyz(const Spectrum& spectrum, const Observer& observer, const Integration& range = {});
std::array<double, 2> chromaticity(const Vec3& xyz);  // x, y (eq. 4-6); (0,0) for black

enum class GamutMapping { Clip, Desaturate, Scale, Unbounded };
// Eq. 9 matrix; then out-of-gamut values are clipped to [0,1], desaturated towards the luminance
// grey until no channel is negative (then clipped above), uniformly scaled so the largest is 1, or
// (Unbounded: scene-referred output, for photometric lights) clipped at 0 only.
Vec3 xyz_to_linear_srgb(const Vec3& xyz, GamutMapping mapping = GamutMapping::Clip);
Vec3 xyz_to_linear_srgb_unclipped(const Vec3& xyz);
double srgb_encode(double linear);  // IEC 61966-2-1, input clamped to [0,1]

}  // namespace fxview::spectral
