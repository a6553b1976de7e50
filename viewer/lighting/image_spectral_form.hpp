// The spectral form of an RGB environment (an image file): each texel's colour uplifted to a
// spectrum by Jakob & Hanika 2019 (spectral/rgb_uplift.hpp), then the image given three spectra of its
// own that every technique reads as it reads the sky's (SpectralForm: L = Σ_k w_k S_k):
//   - the three principal spectral shapes of the image's uplifted texels (second moments, each
//     texel weighted by its solid angle, fading below a tenth of the median luminance; each disc
//     light, the sun, as a quarter of the sphere), so that the image's own spectra are what the
//     three span best;
//   - recombined within that span into the spectra whose colours are the sRGB primaries, each
//     scaled to luminance 1, so that the weights are the texel's colour times the primaries'
//     luminances (0.2127, 0.7152, 0.0722) and every texel's colour is reproduced exactly.
// A texel's spectrum is thus its uplifted spectrum projected (obliquely, colour kept) onto that span;
// `projection_error` says how far. The ground truths (`exact`, `exact_radiance`) read the image's
// texels bilinearly, the disc lights sharp, and uplift each direction's colour itself: the full
// Jakob-Hanika spectrum, not the projection.
#pragma once
#include "lighting/environment_sources.hpp"

namespace fxview::lighting {

// Sets environment.spectral for an environment made from an image.
void add_image_spectral_form(Environment& environment);

// The luminance-weighted RMS difference between texels' uplifted spectra and the form's, relative to
// their RMS (a fraction), over the cube at 32² per face and the discs.
double projection_error(const Environment& environment);

}  // namespace fxview::lighting
