// The sensitivity transforms F_c(D) (spectral/sensitivity_transform.hpp) of every spectrum of the
// library under both observers, tabulated for the GPU (ResourceName "spectral:fourier"): a thin
// film's colour is then a few look-ups per series term instead of a 471-wavelength loop
// (effects/spectral/thinfilm.fx, FresnelFourier and BubbleFourier).
//   S_c(λ) = cmf_c(λ) · light(λ) / Σ ȳ over 360-830 nm at 1 nm, the normalisation of the spectral
//   loops (effects/lib/spectral.glsl with automatic k), so both techniques give the same brightness.
//   F_c oscillates at the sensitivity's mean frequency ν_c = Σ S_c / λ / Σ S_c; the table stores the
//   slowly varying envelope G_c(D) = F_c(D) e^{−i2πDν_c} every kFourierStepNm, where linear
//   interpolation is accurate (its error is at most (2π σ_c h)² / 8 of F_c(0), σ_c the rms spread of
//   1/λ about ν_c: below 2e-5 at h = 8 nm for the library's lights; tests/test_film_fourier.cpp), and the shader multiplies the carrier back.
// Layout: RGBA32F, kFourierSamples texels wide; table t = observer · spectra + spectrum uses GL rows
// 3t (Re G, xyz), 3t + 1 (Im G) and 3t + 2 (texel 0: ν_c per channel; texel k >= 1: the largest
// stored |F| per channel from sample k on, which bounds what the series' remaining terms can add
// far more tightly than F(0) for all but the thinnest films). Beyond the last sample (path
// differences over 32.8 µm) F is taken as 0, the incoherent limit: for daylight and other smooth
// spectra |F| is below 0.2 % of F(0) from 20 µm on, but a fluorescent line spectrum keeps ~20 %, so
// under such a light the second and higher terms of films with n d over ~8 µm lose their coherent
// part (single films reach n d = 12 µm at the sliders' maxima).
#pragma once
#include <vector>

#include "spectral/packing.hpp"
#include "spectral/sensitivity_transform.hpp"
#include "spectral/spectrum.hpp"

namespace fxview::spectral {

constexpr int kFourierSamples = 4096;
constexpr double kFourierStepNm = 8.0;
constexpr int kFourierRowsPerTable = 3;

PackedTexture fourier_table(const std::vector<NamedSpectrum>& spectra, const Observer& cie1931, const Observer& cie1964);

// F(D) for one observer row (0 = CIE 1931, 1 = CIE 1964) and spectrum, interpolated from the stored
// (float) table in double, as the shader does: what the CPU reference uses.
ComplexXyz fourier_lookup(const PackedTexture& table, int observer_row, int spectrum, double path_difference_nm);
// The largest |F_c| over all channels that fourier_lookup can return at this path difference or any
// longer one (0 beyond the table).
double fourier_tail_bound(const PackedTexture& table, int observer_row, int spectrum, double path_difference_nm);

}  // namespace fxview::spectral
