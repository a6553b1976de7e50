// The level-of-detail scheme of seed 002 ch. 4.6 (DOMAIN.md §5): the CMFs and spectra are read only
// at support points every 2^(9 - level) nm (level 9: every nm of the 513 samples, level 1: three
// points) and linearly interpolated in between; every nm of the range still enters the sum.
#pragma once
#include <functional>

#include "spectral/colorimetry.hpp"

namespace fxview::spectral {

constexpr int kLodLevels = 9;  // 513 = 2^9 + 1 samples

// Spacing of the support points at `level` (1..9) in nm; UsageError outside.
int lod_spacing(int level);

// f(nm) linearly interpolated between the support points lower, lower + spacing, ..., with upper
// as the last one.
double lod_interpolated(const std::function<double(int)>& f, int nm, int lower, int upper, int spacing);

// XYZ of `spectrum` with CMFs and spectrum interpolated between support points, normalised by
// k = 1 / sum of the interpolated ybar (so a constant 1 still gives Y = 1).
Vec3 spectrum_to_xyz_lod(const Spectrum& spectrum, const Observer& observer, int lower, int upper, int spacing);

// CIELAB (CIE 15) relative to `white`, and the colour difference ΔE*ab (CIE76).
Vec3 xyz_to_lab(const Vec3& xyz, const Vec3& white);
double delta_e_ab(const Vec3& lab1, const Vec3& lab2);

}  // namespace fxview::spectral
