#include "reference/film_fourier.hpp"

#include "optics/film_series.hpp"
#include "optics/thin_film.hpp"

namespace fxview::reference {

spectral::Vec3 film_xyz_fourier(const spectral::SensitivityTransform& transform, const Film& film, int order) {
    spectral::Vec3 xyz{};
    for (const auto polarisation : {optics::Polarisation::S, optics::Polarisation::P}) {
        const optics::FilmSeries series = optics::film_series(film.outer, film.index, film.substrate, film.cos_outer, polarisation, order);
        const double path = 2.0 * film.index * film.thickness_nm * series.cos_film;  // δ = 2π path / λ
        const spectral::Vec3& white = transform.white();
        for (size_t c = 0; c < 3; ++c) xyz[c] += 0.5 * series.c[0].real() * white[c];
        for (int m = 1; m <= order; ++m) {
            const spectral::ComplexXyz f = transform.at(m * path);
            for (size_t c = 0; c < 3; ++c) xyz[c] += (series.c[static_cast<size_t>(m)] * f[c]).real();  // 2 Re(C_m F) × ½
        }
    }
    return xyz;
}

spectral::Vec3 film_xyz_exact(const spectral::Observer& observer, const spectral::Spectrum& light, const Film& film,
                              const spectral::Integration& range) {
    const optics::Stack stack{film.outer, {{film.index, film.thickness_nm}}, film.substrate};
    double luminance = 0;
    spectral::Vec3 xyz{};
    for (int nm = range.lower; nm <= range.upper; nm += range.step) {
        const double r = optics::transfer_matrix_reflectance(stack, nm, film.cos_outer) * light.at(nm);
        xyz[0] += observer.x.at(nm) * r;
        xyz[1] += observer.y.at(nm) * r;
        xyz[2] += observer.z.at(nm) * r;
        luminance += observer.y.at(nm) * light.at(nm);
    }
    for (double& v : xyz) v /= luminance;
    return xyz;
}

}  // namespace fxview::reference
