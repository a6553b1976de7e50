// How much of the thesis' highlight lobes lies above the surface, as a table for the GPU: with it a
// few lobe directions need only estimate the mean light under the lobe, and uniform light comes out
// right at every angle to the table's accuracy (2e-4, 2e-3 at grazing; 32 directions counting those
// below the horizon would step by 1/32 of the lobe).
#pragma once
#include "lighting/image_based_lighting.hpp"

namespace fxview::lighting {

// (1/π) ∫ over l with n·l > 0 of (r·l)^p (Phong, r the mirror direction of v) and of (n·h)^p (Blinn),
// both functions of n·v and p alone, in units of the whole Phong lobe's 2 / (p + 1): so a head-on Phong
// lobe reads 1 and the table varies slowly in p (Phong's rows interpolate to 1e-4, not 1 %). Tabulated as
// DfgTable lays values out: n·v = i / (size - 1) across, log2(p) / 8 = j / (size - 1) up (p from 1 to
// 256); x Phong, y Blinn, z 0. Multiply by lobe_mass_unit(p).
DfgTable make_lobe_mass_table(int size = 64);
// The 64² table, made once per process (a constant of the lobes: every environment shares it; making
// it takes ~0.4 s, which each effect reopened in a sweep would pay again).
const DfgTable& lobe_mass_table();
double lobe_mass_row(double power);  // log2(p) / 8 clamped to [0, 1]: the table's second coordinate
inline double lobe_mass_unit(double power) { return 2.0 / (power + 1.0); }

}  // namespace fxview::lighting
