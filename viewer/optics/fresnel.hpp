// Fresnel amplitude coefficients at one interface, for real or complex refractive indices
// n̂ = n + iκ (DOMAIN.md §3; seed 002 eq. 46, Code 14). Double precision, GL-free: the exact
// physics the thin-film CPU references and the optics tests build on.
#pragma once
#include <complex>

namespace fxview::optics {

using Complex = std::complex<double>;

// s: electric field perpendicular to the plane of incidence (r⊥, TE); p: parallel (r∥, TM).
enum class Polarisation { S, P };

// cos θt in medium `n_t` for light arriving at cos θi from medium `n_i` (Snell's law with the square
// on n_i/n_t that the printed eq. 58/59 drop). Complex for absorbing media and beyond the critical
// angle; the root with Re ≥ 0 (Im ≥ 0 past the critical angle) is the one whose wave decays.
Complex refracted_cos(Complex n_i, Complex n_t, Complex cos_i);

struct Amplitudes {
    Complex r, t;
};

// Amplitude reflection and transmission coefficients in Code 14's convention:
// r⊥ = (n_i cos_i − n_t cos_t)/(n_i cos_i + n_t cos_t), r∥ = (n_t cos_i − n_i cos_t)/(n_t cos_i + n_i cos_t).
Amplitudes fresnel(Complex n_i, Complex n_t, Complex cos_i, Complex cos_t, Polarisation polarisation);

// |r|² averaged over both polarisations (unpolarised light) at a bare interface.
double interface_reflectance(Complex n_i, Complex n_t, double cos_i);

}  // namespace fxview::optics
