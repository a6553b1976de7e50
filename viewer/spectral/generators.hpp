// Spectra made from formulas: Planck's black body, CIE daylight at any correlated colour
// temperature (CIE 15 from the S0, S1, S2 basis), and synthetic box, Gaussian and ramp spectra.
#pragma once
#include <string>

#include "spectral/spectrum.hpp"

namespace fxview::spectral {

// Spectral radiance of a black body at `kelvin`, normalised to 1 at 560 nm.
Spectrum blackbody(double kelvin);
// CIE daylight D at a correlated colour temperature in 4000..25000 K, normalised to 100 at 560 nm
// (as the CIE tables are). The basis comes from colord-data's CIE-1986-daylight-SPD.cmf.
Spectrum cie_daylight(double kelvin, const std::string& colord_dir = "/usr/share/colord");
Spectrum box(double from_nm, double to_nm, double height = 1.0);
Spectrum gaussian(double centre_nm, double sigma_nm, double height = 1.0);
Spectrum ramp(double from_nm, double to_nm);  // 0 at from_nm rising linearly to 1 at to_nm (held outside)

}  // namespace fxview::spectral
