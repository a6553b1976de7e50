// A film's colour by the Fourier series (optics/film_series.hpp + spectral/sensitivity_transform.hpp)
// and by its ground truth, the 1 nm spectral loop over transfer-matrix reflectances; the pair the
// error study (`fxview spectra film-error`, docs/thin-films.md) compares. XYZ relative to the light
// (a perfect reflector has Y = 1), unpolarised (the mean of s and p).
#pragma once
#include "optics/fresnel.hpp"
#include "spectral/sensitivity_transform.hpp"

namespace fxview::reference {

struct Film {
    double outer = 1.0, index = 1.33;   // lossless outer medium and film
    optics::Complex substrate{1.0, 0.0};  // n + iκ
    double thickness_nm = 300;
    double cos_outer = 1.0;  // cos θ0 of the light in the outer medium
};

spectral::Vec3 film_xyz_fourier(const spectral::SensitivityTransform& transform, const Film& film, int order);
spectral::Vec3 film_xyz_exact(const spectral::Observer& observer, const spectral::Spectrum& light, const Film& film,
                              const spectral::Integration& range = {});

}  // namespace fxview::reference
