// A film's colour by the Fourier series (optics/film_series.hpp + spectral/sensitivity_transform.hpp)
// and by its ground truth, the 1 nm spectral loop over transfer-matrix reflectances; the pair the
// error study (`fxview spectra film-error`, docs/thin-films.md) compares. XYZ relative to the light
// (a perfect reflector has Y = 1), unpolarised (the mean of s and p).
#pragma once
#include <array>
#include <optional>

#include "optics/fresnel.hpp"
#include "spectral/packing.hpp"
#include "spectral/sensitivity_transform.hpp"

namespace fxview::reference {

struct SingleFilm {
    double outer = 1.0, index = 1.33;   // lossless outer medium and film
    optics::Complex substrate{1.0, 0.0};  // n + iκ
    double thickness_nm = 300;
    double cos_outer = 1.0;  // cos θ0 of the light in the outer medium
    // The standard deviation of a Gaussian spread of thicknesses about thickness_nm (a film that varies
    // within a pixel): the series' terms averaged over it (film_xyz_fourier_table); 0 for none.
    double thickness_spread_nm = 0.0;
    // The standard deviation of cos_outer over a rough film's lobe: a spread of path differences too.
    double cos_outer_spread = 0.0;
};

spectral::Vec3 film_xyz_fourier(const spectral::SensitivityTransform& transform, const SingleFilm& film, int order);

// The shipped techniques' rule (thinfilm.fx FresnelFourier / BubbleFourier): at most `order` terms,
// each F(m D) looked up in the GPU's table (spectral/fourier_table.hpp, normalised by 1 / Σ ȳ), the
// terms stopped once a bound on all that is left, relative to the light's largest channel, falls
// below kSeriesTermLimit. Empty where the series does not serve: no series (the film past its
// critical angle), or `order` terms would leave more than kSeriesTailLimit unaccounted (thin films
// near grazing incidence, |x| -> 1); the technique then integrates exactly.
struct SeriesTechnique {
    int order = 16;
    double weight_s = 0.5, weight_p = 0.5;  // polarisation of the light
};
constexpr double kSeriesTailLimit = 1e-3, kSeriesTermLimit = 1e-5;
std::optional<spectral::Vec3> film_xyz_fourier_table(const spectral::PackedTexture& table, int observer_row, int light,
                                                     const SingleFilm& film, const SeriesTechnique& technique);
// The same under a light Σ_k w_k S_k of the table's spectra first .. first + count − 1 (the sky's
// spectral form, environment:fourier): the series is linear in the light, so each term sums the
// weighted transforms; the stopping rule bounds the rest by Σ_k |w_k| (spectrum k's bound) relative
// to the combined light's largest channel. A light with no luminance in any channel gives black.
struct TableLight {
    int first = 0, count = 1;
    std::array<double, 3> weights{1.0, 0.0, 0.0};
};
std::optional<spectral::Vec3> film_xyz_fourier_table(const spectral::PackedTexture& table, int observer_row, const TableLight& light,
                                                     const SingleFilm& film, const SeriesTechnique& technique);
spectral::Vec3 film_xyz_exact(const spectral::Observer& observer, const spectral::Spectrum& light, const SingleFilm& film,
                              const spectral::Integration& range = {});

}  // namespace fxview::reference
