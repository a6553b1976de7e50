// A rough film (thinfilm.fx's Roughness): the environment it mirrors seen through a glossy lobe, in
// a split form (as real-time renderers treat Fresnel under prefiltered environments): the film's
// reflectance at the lobe's mean half-vector angle times the radiance averaged under the lobe. `compare
// --ground-truth` measures it against the lobe's integral with the film at each direction's half
// vector (docs/thin-films.md). CPU twin: EnvironmentLookup::spectral_lobe_mean.
#pragma once
#include "environment_spectral_lobes.glsl"

// A rough film's lobe: Phong (r·l)^p about the mirror direction with p = (1/α² − 1)/2 for α =
// Roughness² (a Blinn (n·h)^(4p), Walter's match of a GGX lobe of width α), at most 1e5.
float film_lobe_power() {
    float alpha = max(Roughness * Roughness, 1e-3);
    return clamp((1.0 / (alpha * alpha) - 1.0) / 2.0, 1.0, 1e5);
}

// The environment's weights averaged under that lobe (environment_spectral_lobes.glsl's gather over
// the lobe's mass above the surface): what a rough mirror sees.
vec3 film_rough_weights(vec3 n, vec3 v, float power) {
    float mass = spectral_lobe_mass(dot(n, v), power).x;
    return mass > 0.0 ? spectral_environment_highlight(n, v, false, power) / mass : vec3(0.0);
}


// The angles the film is seen at through the lobe: the mean (x) and standard deviation (y) of v·h (h
// the half vector of v and l) over 32 of the lobe's directions above the surface. At grazing views the
// lobe's half vectors lie nearer the normal than the eye, and a broad lobe's film colour follows them;
// the Fourier films turn the spread into a spread of path differences (thin_film_fourier.glsl).
vec2 film_rough_cosine(vec3 n, vec3 v, float power) {
    vec3 r = reflect(-v, n), x, y;
    spectral_frame(r, x, y);
    float sum = 0.0, squares = 0.0, count = 0.0;
    for (int i = 0; i < 32; ++i) {
        float u1 = (float(i) + 0.5) / 32.0, u2 = float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10;
        float c = pow(1.0 - u1, 1.0 / (power + 1.0)), sine = sqrt(max(0.0, 1.0 - c * c)), phi = 6.283185307179586 * u2;
        vec3 l = sine * cos(phi) * x + sine * sin(phi) * y + c * r;
        if (dot(n, l) <= 0.0) continue;
        float c_h = clamp(dot(v, normalize(v + l)), 0.0, 1.0);
        sum += c_h;
        squares += c_h * c_h;
        count += 1.0;
    }
    if (!(count > 0.0)) return vec2(clamp(dot(n, v), 0.0, 1.0), 0.0);
    float mean = sum / count;
    return vec2(mean, sqrt(max(squares / count - mean * mean, 0.0)));
}
