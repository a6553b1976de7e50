#include "reference/film_fourier.hpp"

#include <algorithm>

#include "optics/film_series.hpp"
#include "spectral/fourier_table.hpp"
#include "optics/thin_film.hpp"

namespace fxview::reference {

spectral::Vec3 film_xyz_fourier(const spectral::SensitivityTransform& transform, const SingleFilm& film, int order) {
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

std::optional<spectral::Vec3> film_xyz_fourier_table(const spectral::PackedTexture& table, int observer_row, int light,
                                                     const SingleFilm& film, const SeriesTechnique& technique) {
    return film_xyz_fourier_table(table, observer_row, TableLight{light, 1, {1.0, 0.0, 0.0}}, film, technique);
}

std::optional<spectral::Vec3> film_xyz_fourier_table(const spectral::PackedTexture& table, int observer_row, const TableLight& light,
                                                     const SingleFilm& film, const SeriesTechnique& technique) {
    const double ratio = film.outer / film.index;
    if ((1.0 - ratio * ratio) + ratio * ratio * film.cos_outer * film.cos_outer <= 0.0) return std::nullopt;
    const int order = std::max(technique.order, 1);
    const optics::FilmSeries s = optics::film_series(film.outer, film.index, film.substrate, film.cos_outer, optics::Polarisation::S, order);
    const optics::FilmSeries p = optics::film_series(film.outer, film.index, film.substrate, film.cos_outer, optics::Polarisation::P, order);
    // Where |x| = 1 (grazing incidence) every C_m is 0: nothing is left to bound.
    const auto decay = [](const optics::FilmSeries& series) { return std::abs(series.ratio) < 1.0 ? 1.0 / (1.0 - std::abs(series.ratio)) : 0.0; };
    const double decay_s = decay(s), decay_p = decay(p);
    const auto coefficient = [&](int m) {
        return std::pair{technique.weight_s * s.c[static_cast<size_t>(m)], technique.weight_p * p.c[static_cast<size_t>(m)]};
    };
    const double path = 2.0 * film.index * film.thickness_nm * s.cos_film;
    // The thicknesses' spread and a rough film's spread of angles (Snell: dcos θ1 / dcos θ0 = (n0/n1)² cos θ0 / cos θ1), independent.
    const double angle_spread = ratio * ratio * film.cos_outer / s.cos_film * film.cos_outer_spread;
    const double path_spread = 2.0 * film.index * std::sqrt(std::pow(film.thickness_spread_nm * s.cos_film, 2) + std::pow(film.thickness_nm * angle_spread, 2));
    const auto lookup = [&](double path_difference, double spread = 0.0) {
        spectral::ComplexXyz sum{};
        for (int k = 0; k < light.count; ++k) {
            const spectral::ComplexXyz f = spectral::fourier_lookup(table, observer_row, light.first + k, path_difference, spread);
            for (size_t i = 0; i < 3; ++i) sum[i] += light.weights[static_cast<size_t>(k)] * f[i];
        }
        return sum;
    };
    const auto tail_bound = [&](double path_difference) {
        double bound = 0;
        for (int k = 0; k < light.count; ++k)
            bound += std::abs(light.weights[static_cast<size_t>(k)]) * spectral::fourier_tail_bound(table, observer_row, light.first + k, path_difference);
        return bound;
    };
    const spectral::ComplexXyz white = lookup(0.0);
    const double brightest = std::max({white[0].real(), white[1].real(), white[2].real()});
    if (!(brightest > 0.0)) return spectral::Vec3{};
    // What terms m, m+1, ... can add at most, relative to the light: 2 Σ_{k >= m} |C_k| max|F(k D)|
    // <= 2 |C_m| / (1 − |x|) · (the largest |F| from m D on).
    const auto left_from = [&](int m) {
        const auto [c_s, c_p] = coefficient(std::min(m, order));
        const bool beyond = m > order;  // C_{order+1} = C_order x
        const double scale_s = beyond ? std::abs(s.ratio) : 1.0, scale_p = beyond ? std::abs(p.ratio) : 1.0;
        return 2.0 * (std::abs(c_s) * scale_s * decay_s + std::abs(c_p) * scale_p * decay_p) *
               tail_bound(m * path) / brightest;
    };
    if (!(left_from(order + 1) <= kSeriesTailLimit)) return std::nullopt;
    spectral::Vec3 xyz{};
    for (size_t i = 0; i < 3; ++i) xyz[i] = (technique.weight_s * s.c[0].real() + technique.weight_p * p.c[0].real()) * white[i].real();
    const double table_end = spectral::kFourierStepNm * (spectral::kFourierSamples - 1);
    for (int m = 1; m <= order; ++m) {
        const double left = left_from(m);
        if (left < kSeriesTermLimit) break;
        // The table has no F past its end: drop the rest where it adds little, else the exact sum.
        if (m * path >= table_end) {
            if (left > kSeriesTailLimit) return std::nullopt;
            break;
        }
        const auto [c_s, c_p] = coefficient(m);
        const spectral::ComplexXyz transform = lookup(m * path, m * path_spread);
        for (size_t i = 0; i < 3; ++i) xyz[i] += 2.0 * ((c_s + c_p) * transform[i]).real();
    }
    return xyz;
}

spectral::Vec3 film_xyz_exact(const spectral::Observer& observer, const spectral::Spectrum& light, const SingleFilm& film,
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
