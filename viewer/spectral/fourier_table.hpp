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
// far more tightly than F(0) for all but the thinnest films; the last texel holds a bound on |F|
// past the table up to kFourierBeyondNm, from samples of F and F' with the curvature's limit in
// between, and every texel's bound includes it; past kFourierBeyondNm it is assumed, not bounded). Beyond the last sample (path differences over 32.8 µm) the table has no F: for
// daylight and other smooth spectra |F| is below 0.2 % of F(0) there, but a fluorescent line
// spectrum keeps up to 64 % (F11 near 62 µm, the return of its 5 nm comb), so the techniques drop
// the terms past the table only where the stored bound says they add less than kSeriesTailLimit,
// and take the exact sum otherwise (viewer/reference/film_fourier.hpp).
#pragma once
#include <vector>

#include "spectral/packing.hpp"
#include "spectral/sensitivity_transform.hpp"
#include "spectral/spectrum.hpp"

namespace fxview::spectral {

constexpr int kFourierSamples = 4096;
constexpr double kFourierStepNm = 8.0;
constexpr int kFourierRowsPerTable = 3;
constexpr double kFourierBeyondNm = 65536.0;  // twice the table's reach: F11's comb returns near 62 µm

PackedTexture fourier_table(const std::vector<NamedSpectrum>& spectra, const Observer& cie1931, const Observer& cie1964);

// F(D) for one observer row (0 = CIE 1931, 1 = CIE 1964) and spectrum, interpolated from the stored
// (float) table in double, as the shader does: what the CPU reference uses. `path_spread_nm` = σ: the
// mean of F over path differences spread as a Gaussian of that standard deviation,
// ∫ S(ν') e^{i2πν'D} exp(−2π²ν'²σ²) dν', its Gaussian expanded to second order about the channel's mean
// frequency ν: exp(−2π²ν²σ²) (G + i 2π σ² ν G' + ½ σ² (1 − (2πνσ)²) G'') e^{i2πDν}, G' the envelope's
// slope between samples, G'' its second difference about the sample below (the first above at 0).
ComplexXyz fourier_lookup(const PackedTexture& table, int observer_row, int spectrum, double path_difference_nm, double path_spread_nm = 0.0);
// The largest |F_c| over all channels at this path difference or any longer one: fourier_lookup's
// values within the table, the sampled maximum past it (which fourier_lookup returns as 0).
double fourier_tail_bound(const PackedTexture& table, int observer_row, int spectrum, double path_difference_nm);

}  // namespace fxview::spectral
