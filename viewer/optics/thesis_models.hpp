// The thin-film models of seed 002 ch. 4.4 as documented, approximations included (DOMAIN.md §3):
// fxview implements them faithfully so that its pictures compare with the thesis; the exact ones
// are in thin_film.hpp. Indices: n0 outer medium, n1 film, n2 substrate; lengths in nm.
// The models assume light enters the film; past the film's critical angle (cos θ1 = 0, only when
// n1 < n0) their formulas divide 0 by 0, and the three Fresnel-based ones return 1 (total reflection).
#pragma once

namespace fxview::optics::thesis {

// Eq. 62 / Code 13: I = frac(2 d n1 cos α cosθe / λ), α the refracted light angle (Code 12) and
// cosθe = 0.9 + 0.1 (N·V) (Code 13 line 9). Returns the argument of frac as well, so that callers
// can tell where the discontinuity lies.
struct PathDifference {
    double intensity;
    double cycles;  // 2 d n1 cos α cosθe / λ
};
PathDifference path_difference(double n0, double n1, double thickness_nm, double wavelength_nm, double cos_light,
                               double cos_view);

// Code 15 (Durikovic): ½ Σ_pol ((r10 + r12 cos γ)/(1 + r12 r10 cos γ))², γ = 2π/λ · 2 n1 d cosθ1,
// with Code 14's coefficients r10 (film → outer) and r12 (film → substrate). Not Airy's sum.
double durikovic(double n0, double n1, double n2, double thickness_nm, double wavelength_nm, double cos0);

// Eq. 64/65 ("FresnelAlternative"): t = |1 − r|, trt = t01 r12 t10, trrrt = t01 r12 r10 r12 t10,
// R = (trt sin Δ + trrrt sin 2Δ)² + (r01 cos Δ + trrrt cos 2Δ)², averaged over both polarisations,
// clamped to 1: the sum is truncated after two internal reflections and can exceed 1 (1.18 at
// n0 2.5, n1 3.0, n2 1.0; even Stokes' t01 t10 = 1 − r01² in the same three beams reaches 1.24).
double alternative(double n0, double n1, double n2, double thickness_nm, double wavelength_nm, double cos0);

// Eq. 66 (Fabry-Pérot): F = 4R/(1 − R)², T = 1/(1 + F sin²(Δ/2)), Δ = 2π/λ · 2 n1 d cosθ1; reflected 1 − T
// with the thesis' R = ½(|r∥| + |r⊥|) of the outer/film interface (magnitudes, not squared).
double fabry_perot(double n0, double n1, double thickness_nm, double wavelength_nm, double cos0);

}  // namespace fxview::optics::thesis
