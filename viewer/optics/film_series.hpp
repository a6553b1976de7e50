// The reflectance of one film as a short cosine series in its round-trip phase (Belcour & Barla
// 2017, "A practical extension to microfacet theory for the modeling of varying iridescence"): the
// amplitude of Airy's sum is r = r01 + τ e^{iδ} Σ_k (x e^{iδ})^k with τ = t01 t10 r12 and
// x = r10 r12, so R = |r|² = C0 + 2 Σ_{m≥1} Re(C_m e^{imδ}) with
//     C0  = |r01|² + |τ|² / (1 − |x|²),
//     C_m = conj(r01) τ x^{m−1} + |τ|² x^m / (1 − |x|²),
// δ = 4π n1 d cos θ1 / λ. With wavelength-independent indices the coefficients do not depend on λ:
// only the phase does, so the spectral integral of R against a sensitivity S(λ) reduces to values
// of S's Fourier transform at the optical path differences m · 2 n1 d cos θ1
// (spectral/film_fourier.hpp). The series is exact in the limit of infinite order; |x| < 1 makes its
// terms fall off geometrically. The film must be above its critical angle (n1 ≥ n0 sin θ0, no
// evanescent film), the outer medium and the film lossless; the substrate may absorb (n2 + iκ2).
#pragma once
#include <vector>

#include "optics/fresnel.hpp"

namespace fxview::optics {

struct FilmSeries {
    std::vector<Complex> c;  // c[0] = C0 (real), c[m] = C_m
    double cos_film = 1;     // cos θ1 in the film: the path difference is 2 n1 d cos θ1
    Complex ratio{0.0, 0.0}; // x = r10 r12: C_{m+1} = C_m x for m >= 1
};

// Coefficients up to `order` for one polarisation. Throws Error when the film is evanescent.
FilmSeries film_series(double n0, double n1, Complex n2, double cos0, Polarisation polarisation, int order);

// R at round-trip phase δ from the coefficients (truncated at their order).
double evaluate(const FilmSeries& series, double delta);

}  // namespace fxview::optics
