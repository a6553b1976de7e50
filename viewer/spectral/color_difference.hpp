// Colour differences between CIELAB colours: CIEDE2000 (CIE 142-2001), in the form of Sharma, Wu
// and Dalal (2005), whose 34 test pairs tests/test_spectral.cpp checks. ΔE*ab (CIE76) is beside
// CIELAB in level_of_detail.hpp.
#pragma once
#include "spectral/colorimetry.hpp"

namespace fxview::spectral {

// ΔE00 between two L*a*b* colours, with the parametric factors kL = kC = kH = 1.
double delta_e_2000(const Vec3& lab1, const Vec3& lab2);

}  // namespace fxview::spectral
