// A chart of spectra as an 8-bit RGBA image: axes with ticks and labels, a legend, and under the
// wavelength axis the colour of monochromatic light at each wavelength (CIE 1931, sRGB).
#pragma once
#include <vector>

#include "image/image.hpp"
#include "spectral/colorimetry.hpp"
#include "spectral/spectrum.hpp"

namespace fxview::app {

struct PlotOptions {
    int width = 900, height = 520;
    int lower_nm = 360, upper_nm = 830;
    bool normalise = false;  // scale every spectrum to a peak of 1
};

// Returns a linear-light float image (write it as PNG with the default sRGB encoding).
image::FloatImage plot_spectra(const std::vector<spectral::NamedSpectrum>& spectra, const spectral::Observer& observer,
                               const PlotOptions& options);

}  // namespace fxview::app
