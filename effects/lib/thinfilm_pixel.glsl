// What every technique of thinfilm.fx shares per pixel: the film (angles, thickness), what it mirrors
// (the light spectrum, the spectral environment, a sized light's image), a rough film's strata, and
// the sum over wavelengths. Needs thinfilm.fx's parameters. CPU twin: viewer/reference/thin_film_reference.cpp.
#pragma once

struct Film {
    float cos_light, cos_view;
    float cos0;       // cos θ0 in the outer medium, by Incidence
    float cos0_spread;  // its standard deviation over a rough film's lobe (0: smooth)
    float thickness;  // nm, at this fragment
};

// Under a spectral environment (the built-in sky) with Incidence = view, the film mirrors the sky:
// the light at each wavelength is the sky's radiance from the mirror direction of the eye, whose
// spectral weights film_at() finds once per fragment and keeps here.
bool film_under_sky = false;
vec3 film_sky_weights = vec3(0.0);
// With Incidence = view the film also mirrors a sized scene light (a sphere, disc or rectangle;
// area_light.glsl): its radiance in the mirror direction, over the uniform sky's (π x the lamp's,
// whose irradiance is the sky's at 1), added to the light spectrum. `film_footprint` carries the
// image's blur (how far the mirror direction turns across the pixel) to the CPU reference.
float film_lamp = 0.0;
vec4 film_footprint = vec4(0.0);

// The eye's mirror direction about `normal`.
vec3 mirror_of_eye(vec3 position, vec3 normal) { return reflect(-normalize(CameraPosition - position), normalize(normal)); }

#include "film_roughness.glsl"  // a rough film's lobe and what it sees of the environment

// A rough film's strata of its lobe (film_roughness.glsl): every technique sums its colour over
// film_strata_count of them, each taken at its own angle with its own light; a smooth film has one,
// the pixel's film itself. `film_share`: the stratum's part of a uniform sky's and a lamp's light.
// The techniques loop over them as `do { ... } while (++stratum < film_strata_count)`: llvmpipe runs
// a for loop's body once more, masked, to find it done, which costs a smooth film a second pass.
FilmStrata film_strata;
int film_strata_count = 1;
float film_share = 1.0;
float film_stratum_lamp = 0.0;  // the sized light's part in the stratum (a smooth film: film_lamp)

vec3 film_stratum_weights(int s) { return s == 0 ? film_strata.w0 : s == 1 ? film_strata.w1 : s == 2 ? film_strata.w2 : film_strata.w3; }

bool film_stratum_empty(int s) {
    return film_strata_count > 1 && film_strata.share[s] == 0.0 && film_stratum_weights(s) == vec3(0.0) && film_strata.lamp[s] == 0.0;
}

// Stratum s of the pixel's film `f`: its angle (the pixel's own for a smooth film).
Film film_stratum_angle(Film f, int s) {
    if (film_strata_count > 1) {
        f.cos0 = film_strata.cosine[s];
        f.cos0_spread = film_strata.spread[s];
    }
    return f;
}

// The same, and its light for light_at() (film_sky_weights, film_share).
Film film_stratum(Film f, int s) {
    film_share = film_strata_count > 1 ? film_strata.share[s] : 1.0;
    film_stratum_lamp = film_strata_count > 1 ? film_strata.lamp[s] : film_lamp;
    if (film_strata_count > 1) film_sky_weights = film_stratum_weights(s);
    return film_stratum_angle(f, s);
}

// `blur`: how far the mirror direction turns across the pixel (fx_pixel_turn of mirror_of_eye).
Film film_at(vec3 position, vec3 normal, vec2 uv, float blur) {
    vec3 n = normalize(normal);
    vec3 v = normalize(CameraPosition - position);
    Film f;
    f.cos_light = clamp(dot(n, normalize(LightPosition - position)), 0.0, 1.0);
    f.cos_view = clamp(dot(n, v), 0.0, 1.0);
    float power = film_lobe_power();
    vec2 seen = Incidence == 0 && Roughness > 0.0 ? film_rough_cosine(n, v, power) : vec2(f.cos_view, 0.0);
    f.cos0 = Incidence == 1 ? f.cos_light : seen.x;
    f.cos0_spread = Incidence == 1 ? 0.0 : seen.y;
    vec2 centred = 2.0 * uv - 1.0;
    f.thickness = Thickness + Variation * max(1.0 - dot(centred, centred), 0.0);
    film_under_sky = Incidence == 0 && spectral_environment();
    vec3 mirror = reflect(-v, n);
    bool rough = Incidence == 0 && Roughness > 0.0;
    if (film_under_sky && !rough) film_sky_weights = spectral_environment_weights(mirror);
    film_strata_count = rough ? 4 : 1;
    film_lamp = Incidence == 0 ? 3.14159265358979323846 * scene_light_radiance(position, mirror, blur) : 0.0;
    // A rough film sees a sized light through its lobe, point by point, in the strata.
    if (rough) film_strata = film_rough_strata(n, v, power, seen, film_under_sky, position, film_lamp);
    if (rough) film_lamp = dot(film_strata.lamp, vec4(1.0));
    film_stratum_lamp = film_lamp;
    film_footprint = vec4(blur, 0.0, 0.0, 0.0);
    return f;
}

// The light at `nm`: the light spectrum, or the sky seen in the mirror direction; and the lamp's image.
float light_at(int nm) {
    float spectrum = spectrum_at(LightSpectrum, nm);
    return (film_under_sky ? spectral_environment_radiance(film_sky_weights, nm) : film_share * spectrum) + film_stratum_lamp * spectrum;
}

// One wavelength's reflected light, weighted by the CMFs; ybar_sum collects k's denominator.
void add_sample(inout vec3 xyz, inout float ybar_sum, int nm, float reflectance) {
    vec3 cmf = cmf_at(nm);
    xyz += light_at(nm) * reflectance * cmf;
    ybar_sum += cmf.y;
}

vec4 film_colour(vec3 xyz, float ybar_sum) { return vec4(xyz_to_srgb(xyz * normalisation(ybar_sum) * Brightness), 1.0); }
