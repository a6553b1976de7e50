// Thin-film interference (seed 002 ch. 3.2.2 and 4.4; DOMAIN.md §3): complex numbers as vec2
// (re, im), Fresnel coefficients in Code 14's convention, the thesis' models, and Hirayama's
// recursion (eq. 67) over a stack of films on a substrate of complex index n + iκ.
#pragma once

const float kTwoPi = 6.28318530718;

// ---- complex arithmetic: vec2(re, im) ----
vec2 c_mul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 c_div(vec2 a, vec2 b) { return vec2(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / dot(b, b); }
// Principal square root (Re >= 0; Im >= 0 on the negative real axis: the decaying wave past the
// critical angle).
vec2 c_sqrt(vec2 z) {
    float r = length(z);
    float re = sqrt(max(0.5 * (r + z.x), 0.0));
    float im = sqrt(max(0.5 * (r - z.x), 0.0));
    return vec2(re, z.y < 0.0 ? -im : im);
}
// exp(i * phase) for a complex phase: an absorbing layer (Im phase > 0) attenuates.
vec2 c_exp_i(vec2 phase) { return exp(-phase.y) * vec2(cos(phase.x), sin(phase.x)); }

// ---- real Fresnel coefficients (Code 12, Code 14) for the thesis' models ----
// cos of the refraction angle in n_t for light from n_i at cos_i (eq. 58/59 with the square, as in
// Code 12); 0 past the critical angle. cos_t² = 1 - ratio² (1 - cos_i²) is summed as
// (1 - ratio²) + ratio² cos_i²: near grazing incidence on equal indices the printed form rounds
// 1 - cos_i² to 1 and returns cos_t = 0 for cos_i ≈ 1e-4, an interface that reflects everything.
float refracted_cos(float n_i, float n_t, float cos_i) {
    float ratio = n_i / n_t;
    return sqrt(max((1.0 - ratio * ratio) + ratio * ratio * cos_i * cos_i, 0.0));
}
// Code 14: (r∥, r⊥) for light in n_i at cos_i meeting n_t at cos_t. Both denominators vanish only
// at grazing incidence on equal indices, where there is no interface: r = 0 there (the limit as
// n_t -> n_i), not 0/0.
vec2 fresnel_combined(float cos_i, float cos_t, float n_i, float n_t) {
    float p = n_t * cos_i + n_i * cos_t, s = n_i * cos_i + n_t * cos_t;
    return vec2(p > 0.0 ? (n_t * cos_i - n_i * cos_t) / p : 0.0, s > 0.0 ? (n_i * cos_i - n_t * cos_t) / s : 0.0);
}

// ---- complex Fresnel coefficients for the exact models ----
// cos θ in a medium of index n (complex) for light from a real n0 at cos0 (Snell's invariant n0 sin θ0).
// Summed as (1 - ratio²) + ratio² cos0², as refracted_cos.
vec2 refracted_cos_c(float n0, vec2 n, float cos0) {
    vec2 ratio = c_div(vec2(n0, 0.0), n), ratio2 = c_mul(ratio, ratio);
    return c_sqrt((vec2(1.0, 0.0) - ratio2) + ratio2 * (cos0 * cos0));
}
struct Amplitude { vec2 s; vec2 p; };
// A vanishing denominator means grazing incidence on equal indices: no interface, r = 0.
Amplitude fresnel_c(vec2 n_i, vec2 cos_i, vec2 n_t, vec2 cos_t) {
    vec2 a = c_mul(n_i, cos_i), b = c_mul(n_t, cos_t), c = c_mul(n_t, cos_i), d = c_mul(n_i, cos_t);
    return Amplitude(dot(a + b, a + b) > 0.0 ? c_div(a - b, a + b) : vec2(0.0),
                     dot(c + d, c + d) > 0.0 ? c_div(c - d, c + d) : vec2(0.0));
}
// One step of eq. 67 from the bottom up: the amplitude reflected by interface r above a layer of
// phase thickness `phase` whose lower boundary reflects gamma.
vec2 hirayama_step(vec2 r, vec2 gamma, vec2 phase) {
    vec2 g = c_mul(gamma, c_exp_i(2.0 * phase));
    return c_div(r + g, vec2(1.0, 0.0) + c_mul(r, g));
}
