#include "optics/film_series.hpp"

#include <cmath>

#include "core/error.hpp"

namespace fxview::optics {

FilmSeries film_series(double n0, double n1, Complex n2, double cos0, Polarisation polarisation, int order) {
    const Complex cos1 = refracted_cos(n0, n1, cos0), cos2 = refracted_cos(n0, n2, cos0);
    if (std::abs(cos1.imag()) > 1e-12) throw Error("film series: the film is beyond its critical angle (evanescent): no Fourier series");
    const Amplitudes a01 = fresnel(n0, n1, cos0, cos1, polarisation), a10 = fresnel(n1, n0, cos1, cos0, polarisation);
    const Complex r12 = fresnel(n1, n2, cos1, cos2, polarisation).r;
    const Complex r01 = a01.r, tau = a01.t * a10.t * r12, x = a10.r * r12;
    // At grazing incidence r01 = −1: τ = 0 and |x| may be 1; T is 0 there (not 0/0), and so are all C_m.
    const double tail = std::norm(tau) > 0 ? std::norm(tau) / (1.0 - std::norm(x)) : 0.0;
    FilmSeries series;
    series.cos_film = cos1.real();
    series.ratio = x;
    series.c.resize(static_cast<size_t>(order) + 1);
    series.c[0] = std::norm(r01) + tail;
    Complex x_power(1.0, 0.0);  // x^{m−1}
    for (int m = 1; m <= order; ++m) {
        series.c[static_cast<size_t>(m)] = std::conj(r01) * tau * x_power + tail * x_power * x;
        x_power *= x;
    }
    return series;
}

double evaluate(const FilmSeries& series, double delta) {
    double r = series.c[0].real();
    for (size_t m = 1; m < series.c.size(); ++m) r += 2.0 * (series.c[m] * std::polar(1.0, static_cast<double>(m) * delta)).real();
    return r;
}

}  // namespace fxview::optics
