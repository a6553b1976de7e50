// The Fourier-domain films of effects/spectral/thinfilm.fx (FresnelFourier, BubbleFourier), included
// by it after its Film, light_at(), film_under_sky and exact sums: they are this file's callers and
// fall back to them. Its parameters (FilmFourier, SeriesOrder, Polarisation) are thinfilm.fx's.
#pragma once

// ---- Fourier-domain films (Belcour & Barla 2017; docs/thin-films.md) ----
// With wavelength-independent indices, a film's reflectance is a cosine series in its round-trip
// phase δ = 2π D / λ, D = 2 n1 d cos θ1:  R = C0 + 2 Σ_m Re(C_m e^{i m δ}),
//     C0 = r01² + T,  C_m = (r01 τ + T x) x^{m−1},  τ = (1 − r01²) r12,  x = −r01 r12,  T = |τ|² / (1 − |x|²),
// with r01 real (a lossless outer medium and film) and r12 complex (the substrate may absorb). Its
// integral against light × CMF is C0 F(0) + 2 Σ_m Re(C_m F(m D)), F the light's sensitivity
// transform, precomputed from our own 1 nm tables (spectral:fourier). The polarisations share F, so
// their weighted coefficients are summed first. Terms stop at SeriesOrder or as soon as a bound on
// everything left, 2 |C_m| / (1 − |x|) times the largest |F| from m D on, falls below 1e-5 of the
// light. Past the film's critical angle
// (a film less dense than the outer medium) the wave in the film decays and no series exists, and
// near grazing incidence SeriesOrder terms may not converge: those fragments take the exact 1 nm
// sum (Airy) instead.
uniform sampler2D FilmFourier < string ResourceName = "spectral:fourier"; string Format = "32F"; string Filter = "nearest"; string Wrap = "clamp"; >;
uniform int SeriesOrder < string UIName = "Series terms"; int UIMin = 1; int UIMax = 64; string UIGroup = "Fourier series";
                          string UIHelp = "At most this many terms of the interference series; terms too small to matter are skipped, and where this many would leave more than 0.1 % of reflectance out (near grazing incidence) the exact wavelength sum is used"; > = 16;
uniform float ThicknessSpread < string UIName = "Thickness spread"; float UIMin = 0; float UIMax = 300; float UIStep = 1; string UIUnits = "nm";
                               string UIGroup = "Fourier series";
                               string UIHelp = "A film whose thickness varies within what a pixel sees (a Gaussian of this standard deviation about Thickness): each term of the series is averaged over it, so thick films wash out towards white as real ones do (Belcour & Barla 2017)"; > = 0.0;
uniform int Polarisation < string UIName = "Polarisation"; string UIWidget = "combo"; string UIItems = "unpolarised|s (TE)|p (TM)"; string UIGroup = "Fourier series";
                           string UIHelp = "Polarisation of the incident light (Fourier techniques)"; > = 0;

const float kFourierStep = 8.0;   // nm between samples (viewer/spectral/fourier_table.hpp)
const int kFourierSamples = 4096;
const int kFourierRowsPerTable = 3;
const float kSeriesTailLimit = 1e-3, kSeriesTermLimit = 1e-5;  // viewer/reference/film_fourier.hpp

// Under the built-in sky the light is Σ_k w_k S_k(λ) (environment_spectral.glsl), and the series is
// linear in the light: the sky's three spectra have tables of their own (environment:fourier, same
// layout), and the film's colour is the weighted sum of the three series, with one set of coefficients.
uniform sampler2D FilmSkyFourier < string ResourceName = "environment:fourier"; string Format = "32F"; string Filter = "nearest"; string Wrap = "clamp"; >;

// F(D) = G(D) e^{i 2π D ν}: the stored envelope G, interpolated, times the carrier at the
// sensitivity's mean frequency ν (per channel). 0 beyond the table: the incoherent limit. Averaged
// over path differences spread as a Gaussian of standard deviation σ = `spread` about D, F becomes
// ∫ S(ν') e^{i2πν'D} exp(−2π²ν'²σ²) dν'; with the Gaussian expanded to second order about ν (the rest
// of the channel's frequencies), that is exp(−2π²ν²σ²) (G + i 2π σ² ν G' + ½ σ² (1 − (2πνσ)²) G'')
// e^{i2πDν}, G' the envelope's slope between the two samples, G'' its second difference.
void sensitivity_at(sampler2D table, int row, vec3 centre, float path, float spread, out vec3 re, out vec3 im) {
    float x = path / kFourierStep;
    re = vec3(0.0);
    im = vec3(0.0);
    if (x >= float(kFourierSamples - 1)) return;
    int i = int(x);
    float t = x - float(i);
    vec3 envelope_re = mix(texelFetch(table, ivec2(i, row), 0).rgb, texelFetch(table, ivec2(i + 1, row), 0).rgb, t);
    vec3 envelope_im = mix(texelFetch(table, ivec2(i, row + 1), 0).rgb, texelFetch(table, ivec2(i + 1, row + 1), 0).rgb, t);
    vec3 angle = kTwoPi * fract(path * centre);
    vec3 phase_spread = kTwoPi * centre * spread;
    vec3 damping = exp(-0.5 * phase_spread * phase_spread);
    if (spread > 0.0) {
        vec3 tilt = kTwoPi * spread * spread * centre / kFourierStep;  // times the envelope's step
        vec3 slope_re = texelFetch(table, ivec2(i + 1, row), 0).rgb - texelFetch(table, ivec2(i, row), 0).rgb;
        vec3 slope_im = texelFetch(table, ivec2(i + 1, row + 1), 0).rgb - texelFetch(table, ivec2(i, row + 1), 0).rgb;
        // The second-order term ½ σ² (1 − (2πνσ)²) G'', G'' by the second difference about sample j.
        int j = max(i, 1);
        vec3 bend = 0.5 * spread * spread * (1.0 - phase_spread * phase_spread) / (kFourierStep * kFourierStep);
        vec3 curve_re = texelFetch(table, ivec2(j + 1, row), 0).rgb - 2.0 * texelFetch(table, ivec2(j, row), 0).rgb + texelFetch(table, ivec2(j - 1, row), 0).rgb;
        vec3 curve_im = texelFetch(table, ivec2(j + 1, row + 1), 0).rgb - 2.0 * texelFetch(table, ivec2(j, row + 1), 0).rgb +
                        texelFetch(table, ivec2(j - 1, row + 1), 0).rgb;
        envelope_re += bend * curve_re - tilt * slope_im;
        envelope_im += bend * curve_im + tilt * slope_re;
    }
    vec3 c = cos(angle) * damping, s = sin(angle) * damping;
    re = envelope_re * c - envelope_im * s;
    im = envelope_re * s + envelope_im * c;
}

// The largest |F| (any channel) from this path difference on: row + 2 holds it from sample 1 on (the
// last texel: the largest sampled past the table); from sample 0 on it is F(0) itself.
float fourier_tail_bound(sampler2D table, int row, float path) {
    int i = int(min(path / kFourierStep, float(kFourierSamples - 1)));
    vec3 tail = i == 0 ? texelFetch(table, ivec2(0, row), 0).rgb : texelFetch(table, ivec2(i, row + 2), 0).rgb;
    return max(tail.x, max(tail.y, tail.z));
}

// The light of a series: `count` consecutive tables of `table` from GL row `row` on, weighted.
struct SeriesLight {
    int row, count;
    vec3 weights;
};

// The bound of the lights' |F| from this path difference on: Σ_k |w_k| (table k's bound).
float light_tail_bound(sampler2D table, SeriesLight light, float path) {
    float bound = 0.0;
    for (int k = 0; k < light.count; ++k) bound += abs(light.weights[k]) * fourier_tail_bound(table, light.row + k * kFourierRowsPerTable, path);
    return bound;
}

// The exact sum at every nm of the table's range, with its normalisation (1 / Σ ȳ): where no series
// exists. `weights`, `share` and `lamp`: the stratum's light (light_at's film_sky_weights, film_share, film_stratum_lamp).
vec3 exact_film_xyz(Film f, vec2 n2, vec3 weights, float share, float lamp) {
    vec2 n1 = vec2(FilmIndex, 0.0);
    vec2 cos1 = refracted_cos_c(OuterIndex, n1, f.cos0), cos2 = refracted_cos_c(OuterIndex, n2, f.cos0);
    Amplitude r01 = fresnel_c(vec2(OuterIndex, 0.0), vec2(f.cos0, 0.0), n1, cos1);
    Amplitude r12 = fresnel_c(n1, cos1, n2, cos2);
    vec2 path = kTwoPi * f.thickness * c_mul(n1, cos1);
    vec2 weight = Polarisation == 1 ? vec2(1.0, 0.0) : Polarisation == 2 ? vec2(0.0, 1.0) : vec2(0.5);
    vec3 xyz = vec3(0.0);
    float ybar_sum = 0.0;
    for (int nm = 360; nm <= 830; ++nm) {
        vec2 s = hirayama_step(r01.s, r12.s, path / float(nm));
        vec2 p = hirayama_step(r01.p, r12.p, path / float(nm));
        vec3 cmf = texelFetch(CmfFloat, ivec2(nm - 360, Observer), 0).rgb;
        float spectrum = spectrum_at(LightSpectrum, nm);
        float light = (film_under_sky ? spectral_environment_radiance(weights, nm) : share * spectrum) + lamp * spectrum;
        xyz += light * (weight.x * dot(s, s) + weight.y * dot(p, p)) * cmf;
        ybar_sum += cmf.y;
    }
    return xyz / ybar_sum;
}

// The series' XYZ (before Brightness) under `light`'s tables; false where it does not serve (see above).
bool fourier_film_xyz(Film f, vec2 n2, sampler2D table, SeriesLight light, out vec3 xyz) {
    xyz = vec3(0.0);
    float ratio = OuterIndex / FilmIndex;
    float cos1_squared = (1.0 - ratio * ratio) + ratio * ratio * f.cos0 * f.cos0;  // as refracted_cos
    if (cos1_squared <= 0.0) return false;
    float cos1 = sqrt(cos1_squared);
    vec2 cos2 = refracted_cos_c(OuterIndex, n2, f.cos0);
    Amplitude r01 = fresnel_c(vec2(OuterIndex, 0.0), vec2(f.cos0, 0.0), vec2(FilmIndex, 0.0), vec2(cos1, 0.0));
    Amplitude r12 = fresnel_c(vec2(FilmIndex, 0.0), vec2(cos1, 0.0), n2, cos2);
    vec2 weight = Polarisation == 1 ? vec2(1.0, 0.0) : Polarisation == 2 ? vec2(0.0, 1.0) : vec2(0.5);
    // Per polarisation: x, C0 and the weighted C_1; then C_{m+1} = C_m x.
    vec2 x_s = -r01.s.x * r12.s, x_p = -r01.p.x * r12.p;
    vec2 tau_s = (1.0 - r01.s.x * r01.s.x) * r12.s, tau_p = (1.0 - r01.p.x * r01.p.x) * r12.p;
    // At grazing incidence r01 = -1: τ = 0 and |x| may be 1, where T is 0 (not 0/0) and so are all C_m.
    float tail_s = dot(tau_s, tau_s) > 0.0 ? dot(tau_s, tau_s) / (1.0 - dot(x_s, x_s)) : 0.0;
    float tail_p = dot(tau_p, tau_p) > 0.0 ? dot(tau_p, tau_p) / (1.0 - dot(x_p, x_p)) : 0.0;
    vec2 c_s = weight.x * (r01.s.x * tau_s + tail_s * x_s), c_p = weight.y * (r01.p.x * tau_p + tail_p * x_p);
    float c0 = weight.x * (r01.s.x * r01.s.x + tail_s) + weight.y * (r01.p.x * r01.p.x + tail_p);
    float decay_s = length(x_s) < 1.0 ? 1.0 / (1.0 - length(x_s)) : 0.0, decay_p = length(x_p) < 1.0 ? 1.0 / (1.0 - length(x_p)) : 0.0;

    vec3 white = vec3(0.0);  // F(0) of the light, real
    vec3 centres[3];         // each table's mean frequencies, for the carrier
    for (int k = 0; k < light.count; ++k) {
        white += light.weights[k] * texelFetch(table, ivec2(0, light.row + k * kFourierRowsPerTable), 0).rgb;
        centres[k] = texelFetch(table, ivec2(0, light.row + k * kFourierRowsPerTable + 2), 0).rgb;
    }
    float brightest = max(white.x, max(white.y, white.z));
    if (!(brightest > 0.0)) return true;  // no light (a black direction of the sky): black
    float path = 2.0 * FilmIndex * f.thickness * cos1;
    // Term m: m D spread by m path_spread, from the thicknesses' spread and a rough film's spread of
    // angles (dcos θ1 / dcos θ0 = (n0/n1)² cos θ0 / cos θ1 by Snell), taken as independent.
    float angle_spread = ratio * ratio * f.cos0 / cos1 * f.cos0_spread;
    float path_spread = 2.0 * FilmIndex * sqrt(ThicknessSpread * ThicknessSpread * cos1 * cos1 + f.thickness * f.thickness * angle_spread * angle_spread);
    // What SeriesOrder terms leave out, relative to the light, is at most
    // 2 |C_{order+1}| / (1 − |x|) · (the largest |F| from (order+1) D on). Past kSeriesTailLimit (thin
    // films near grazing incidence, |x| -> 1) the exact sum serves instead.
    float left = 2.0 * (length(c_s) * pow(length(x_s), float(SeriesOrder)) * decay_s + length(c_p) * pow(length(x_p), float(SeriesOrder)) * decay_p)
                 * light_tail_bound(table, light, float(SeriesOrder + 1) * path) / brightest;
    if (!(left <= kSeriesTailLimit)) return false;

    xyz = c0 * white;
    for (int m = 1; m <= SeriesOrder; ++m) {
        float rest = 2.0 * (length(c_s) * decay_s + length(c_p) * decay_p) * light_tail_bound(table, light, float(m) * path) / brightest;
        if (rest < kSeriesTermLimit) break;
        // The table has no F past its end (a line spectrum's comb returns there): drop the rest where
        // it adds little, else the exact sum.
        if (float(m) * path >= kFourierStep * float(kFourierSamples - 1)) {
            if (rest > kSeriesTailLimit) return false;
            break;
        }
        vec2 c = c_s + c_p;
        for (int k = 0; k < light.count; ++k) {
            vec3 re, im;
            sensitivity_at(table, light.row + k * kFourierRowsPerTable, centres[k], float(m) * path, float(m) * path_spread, re, im);
            xyz += light.weights[k] * 2.0 * (c.x * re - c.y * im);
        }
        c_s = c_mul(c_s, x_s);
        c_p = c_mul(c_p, x_p);
    }
    return true;
}

// A rough film's strata (one for a smooth film), each by the series or where it has none (see above)
// by the exact sum. One call site of each, each stratum's light passed rather than set in globals, and
// a do-while loop: llvmpipe pays for every inlined copy of these loops, run or not, for globals
// written in a loop around them, and for the masked extra pass a for loop makes (a smooth film's
// FresnelFourier under the sky, 1024x768: 124 ms a frame with no loop, 171 in a for loop, 212 with
// globals written in it, 236-250 with a second copy; 162 in this form).
vec4 fourier_film_colour(Film pixel, vec2 n2) {
    vec3 sum = vec3(0.0);
    int row = kFourierRowsPerTable * (Observer * (textureSize(FilmFourier, 0).y / (2 * kFourierRowsPerTable)) + LightSpectrum);
    bool rough = film_strata_count > 1;
    int stratum = 0;
    do {
        if (film_stratum_empty(stratum)) continue;
        Film f = film_stratum_angle(pixel, stratum);
        vec3 weights = rough ? film_stratum_weights(stratum) : film_sky_weights, xyz;
        float share = rough ? film_strata.share[stratum] : 1.0, lamp = rough ? film_strata.lamp[stratum] : film_lamp;
        // The sky's three tables (observer · 3 + k); a lamp mirrored besides it (another spectrum): the
        // exact sum. Without the sky the lamp's image has the light's own spectrum and scales the series.
        bool series = film_under_sky ? lamp <= 0.0 && fourier_film_xyz(f, n2, FilmSkyFourier, SeriesLight(kFourierRowsPerTable * 3 * Observer, 3, weights), xyz)
                                     : fourier_film_xyz(f, n2, FilmFourier, SeriesLight(row, 1, vec3(share + lamp, 0.0, 0.0)), xyz);
        sum += series ? xyz : exact_film_xyz(f, n2, weights, share, lamp);
    } while (++stratum < film_strata_count);
    return vec4(xyz_to_srgb(sum * Brightness), 1.0);
}
