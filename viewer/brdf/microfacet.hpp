// Building blocks of microfacet BRDFs (DOMAIN.md §7; seed 004 ch. 3.4, seed 001 slides 12.3-12.4):
// normal distributions, geometry terms and Fresnel factors as plain functions of cosines, in double
// precision. GL-free; the CPU references and the BRDF fitter use them.
#pragma once

namespace fxview::brdf {

// GGX / Trowbridge-Reitz with α = roughness² (seed 004 eq. 8): α² / (π ((n·h)²(α² − 1) + 1)²).
double ggx_distribution(double n_dot_h, double alpha);

// Beckmann: exp(−tan²γ / m²) / (π m² cos⁴γ), normalised so that ∫ D (n·h) dω = 1. Seed 001 prints
// 4 in place of π; `printed_form` reproduces that (its integral is π/4).
double beckmann_distribution(double n_dot_h, double m, bool printed_form = false);

// Smith's G with Schlick-GGX G1(x) = x / (x(1 − k) + k), k = (roughness + 1)² / 8 (seed 004 eq. 9/10).
double smith_schlick_ggx(double n_dot_v, double n_dot_l, double roughness);

// The V-cavity term of Cook-Torrance: min(1, 2(n·h)(n·v)/(v·h), 2(n·h)(n·l)/(v·h)).
double v_cavity_geometry(double n_dot_h, double n_dot_v, double n_dot_l, double v_dot_h);

// Fresnel-Schlick: F0 + (1 − F0)(1 − cos)⁵.
double fresnel_schlick(double f0, double cos_theta);

// The full Fresnel reflectance for unpolarised light at a dielectric of relative index η (seed 001):
// ½ ((g − c)/(g + c))² (1 + ((c(g + c) − 1)/(c(g − c) + 1))²), c = cos, g = √(η² + c² − 1); 1 past
// the critical angle (g² < 0).
double fresnel_dielectric(double eta, double cos_theta);

}  // namespace fxview::brdf
