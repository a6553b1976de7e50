// A rough film (thinfilm.fx's Roughness): the environment it mirrors seen through a glossy lobe. The
// lobe's directions are split into four strata by the angle the film is seen at (v·h, h the half
// vector of the eye and the direction): each stratum brings its own light (the environment's weights
// summed over its directions, the sun's points among them) and takes the film's reflectance at its
// own mean angle (weighted by that light), so that a broad lobe averages the film over four angles and
// the sun in the lobe takes the film's colour near its own half vector. `compare --ground-truth`
// measures it against the lobe's integral with the film at each direction's half vector
// (docs/thin-films.md). CPU twin: viewer/reference/film_strata.cpp.
#pragma once
#include "environment_spectral_lobes.glsl"
#include "area_light.glsl"

// A rough film's lobe: Phong (r·l)^p about the mirror direction with p = (1/α² − 1)/2 for α =
// Roughness² (a Blinn (n·h)^(4p), Walter's match of a GGX lobe of width α), at most 1e5 (Roughness
// below 0.047: a lobe 0.2° wide), at least 1 (Roughness 0.76; UIMax 0.75: broader lobes, up to the
// hemisphere about the mirror direction at 1, span more angles than four strata follow: furnace mean
// CIEDE2000 1.0 there against 0.5 at 0.7).
float film_lobe_power() {
    float alpha = max(Roughness * Roughness, 1e-3);
    return clamp((1.0 / (alpha * alpha) - 1.0) / 2.0, 1.0, 1e5);
}

// The angles the film is seen at through the lobe: the mean (x) and standard deviation (y) of v·h (h
// the half vector of v and l) over 32 of the lobe's directions above the surface. At grazing views the
// lobe's half vectors lie nearer the normal than the eye. They place the strata's edges.
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

// A light of `solid` angle seen through the lobe at `points` points, each standing for a cell of
// side a = √(solid / points): a lobe narrower than that would show them as dots, so the points see the
// lobe widened to a standard deviation of at least 0.6 a (its power at most 1 / (0.6 a)², its mass to
// match), where Gaussians a apart sum to within 2 exp(−2π² 0.36) = 0.2 % of flat.
float film_points_lobe_power(float power, float solid, int points) {
    return min(power, 1.0 / max(0.36 * solid / float(points), 1e-12));
}

// Phong's (r·l)^p for unit r and l, from the chord: exp(p log(1 − d)), d = |r − l|²/2 = 1 − r·l. A
// narrow lobe's value from the dot product errs ~1e-7·p in float (5e-4 at p = 5000), from the chord
// ~1e-5.
float phong_lobe_by_chord(vec3 r, vec3 l, float power) {
    vec3 e = r - l;
    float d = 0.5 * dot(e, e);
    float log_cosine = d < 0.05 ? -d * (1.0 + d * (0.5 + d * (1.0 / 3.0 + d * 0.25))) : log(max(1.0 - d, 1e-30));
    return d < 1.0 ? exp(power * log_cosine) : 0.0;  // nothing behind the mirror direction, at p = 0 too
}

// The four strata of the lobe (film_rough_strata); a stratum with nothing in it has share 0 and no light.
struct FilmStrata {
    vec4 cosine;         // mean v·h per stratum, weighted by the light its directions bring
    vec4 spread;         // v·h's standard deviation within each
    vec4 share;          // the stratum's part of the lobe's directions above the surface (a uniform sky, a lamp)
    vec3 w0, w1, w2, w3; // the environment's weights per stratum: together its mean under the lobe above the surface
    vec4 lamp;           // the scene's sized light per stratum, in the uniform sky's units (as film_lamp)
};

// The strata a direction with v·h = c_h falls in, at the edges μ + σ (−0.674, 0, 0.674) of the lobe's
// v·h (the quartiles of a normal distribution): its shares of the four, split linearly across `soft`
// about each edge (0.1 σ) so that the strata change smoothly with the view. (One-hot, a bright lamp's
// point on an edge moved all its light between two angles on a float rounding of v·h.)
vec4 film_stratum_of(float c_h, vec3 edges, float soft) {
    vec3 above = clamp((c_h - edges) / soft + 0.5, 0.0, 1.0);
    return vec4(1.0 - above.x, above.x - above.y, above.y - above.z, above.z);
}

// Splits the lobe of `power` about the mirror direction of v into strata by v·h, given `seen` (mean and
// standard deviation of v·h, film_rough_cosine). `sky`: under the spectral environment (its weights by
// the filtered gather of spectral_environment_highlight, the disc lights by 16 points each); otherwise a
// uniform light, each direction weighing alike.
// `position`: where the film is, for the scene's sized light (area_light.glsl), seen through the lobe
// at its own points; `mirror_lamp`: its image in the mirror direction, for a lobe with no direction
// above the surface.
FilmStrata film_rough_strata(vec3 n, vec3 v, float power, vec2 seen, bool sky, vec3 position, float mirror_lamp) {
    const float pi = 3.14159265358979323846;
    vec3 edges = seen.x + seen.y * vec3(-0.674, 0.0, 0.674);
    float soft = max(0.1 * seen.y, 1e-6);
    vec3 r = reflect(-v, n), x, y;
    spectral_frame(r, x, y);
    FilmStrata strata;
    strata.w0 = strata.w1 = strata.w2 = strata.w3 = vec3(0.0);
    strata.lamp = vec4(0.0);
    vec4 count = vec4(0.0), light = vec4(0.0), light_c = vec4(0.0), light_c2 = vec4(0.0);
    int samples = spectral_lobe_samples(power);
    for (int i = 0; i < samples; ++i) {
        float u1 = (float(i) + 0.5) / float(samples), u2 = float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10;
        float c = pow(1.0 - u1, 1.0 / (power + 1.0)), sine = sqrt(max(0.0, 1.0 - c * c)), phi = 2.0 * pi * u2;
        vec3 l = sine * cos(phi) * x + sine * sin(phi) * y + c * r;
        float density = (power + 1.0) / (2.0 * pi) * pow(c, power);
        if (dot(n, l) <= 0.0 || !(density > 0.0)) continue;
        vec3 w = sky ? spectral_environment_filtered(l, 1.0 / (float(samples) * density)) : vec3(1.0);
        float c_h = clamp(dot(v, normalize(v + l)), 0.0, 1.0), luminance = w.x + w.y + w.z;  // the spectra have luminance 1
        vec4 at = film_stratum_of(c_h, edges, soft);
        strata.w0 += at.x * w;
        strata.w1 += at.y * w;
        strata.w2 += at.z * w;
        strata.w3 += at.w * w;
        count += at;
        light += at * luminance;
        light_c += at * (luminance * c_h);
        light_c2 += at * (luminance * c_h * c_h);
    }
    float total = count.x + count.y + count.z + count.w;
    if (!(total > 0.0)) {  // no direction above the surface (a bump turned from the eye): as a smooth film, one stratum
        strata.cosine = vec4(seen.x, 0.0, 0.0, 0.0);
        strata.spread = vec4(0.0);
        strata.share = vec4(1.0, 0.0, 0.0, 0.0);
        if (sky) strata.w0 = spectral_environment_weights(r);
        strata.lamp.x = mirror_lamp;
        return strata;
    }
    strata.share = count / total;
    strata.w0 /= total;
    strata.w1 /= total;
    strata.w2 /= total;
    strata.w3 /= total;
    light /= total;
    light_c /= total;
    light_c2 /= total;
    // The disc lights (the sun): 16 points of equal area over each, each point in its own stratum, over
    // the lobe's mass above the surface (the sky's directions are already a mean over it).
    if (sky) {
        vec3 ne = FxSpectralEnvironmentRotation * n, ve = FxSpectralEnvironmentRotation * v, re = reflect(-ve, ne);
        const float golden = pi * (3.0 - sqrt(5.0));
        for (int k = 0; k < kSpectralDiscs; ++k) {
            vec4 place = texelFetch(FxSpectralDiscs, ivec2(2 * k, 0), 0), disc = texelFetch(FxSpectralDiscs, ivec2(2 * k + 1, 0), 0);
            if (!(disc.a > 0.0)) continue;
            float seen_power = film_points_lobe_power(power, 3.14159265358979323846 * place.w * place.w, kSpectralDiscPoints), mass = spectral_lobe_mass(dot(n, v), seen_power).x;
            if (!(mass > 0.0)) continue;
            vec3 dx, dy;
            spectral_frame(place.xyz, dx, dy);
            for (int j = 0; j < kSpectralDiscPoints; ++j) {
                float radius = sqrt((float(j) + 0.5) / float(kSpectralDiscPoints)) * place.w, angle = golden * float(j);
                vec3 l = normalize(place.xyz + tan(radius) * (cos(angle) * dx + sin(angle) * dy));
                if (dot(ne, l) <= 0.0) continue;
                vec3 w = disc.rgb * (disc.a * phong_lobe_by_chord(re, l, seen_power) / float(kSpectralDiscPoints) / pi * FxSpectralEnvironmentIntensity / mass);
                float c_h = clamp(dot(ve, normalize(ve + l)), 0.0, 1.0), luminance = w.x + w.y + w.z;
                vec4 at = film_stratum_of(c_h, edges, soft);
                strata.w0 += at.x * w;
                strata.w1 += at.y * w;
                strata.w2 += at.z * w;
                strata.w3 += at.w * w;
                light += at * luminance;
                light_c += at * (luminance * c_h);
                light_c2 += at * (luminance * c_h * c_h);
            }
        }
    }
    // The scene's sized light the same way: 16 points over a sphere's cone (a sunflower spiral), the
    // flat lights' 34 of area_light.glsl, each bringing π L ΔΩ (r·l)^p / mass (its light in the uniform
    // sky's units). The mass: 2π/(p+1) times the part of the lobe's directions above the surface.
    if (flat_light() || LightRadius > 0.0) {
        bool flat_lamp = flat_light();
        vec3 to_centre = LightPosition - position;
        float distance = max(length(to_centre), 1e-12);
        vec3 c = to_centre / distance, cx, cy;
        spectral_frame(c, cx, cy);
        // The sphere's cone by its sine and cosine (llvmpipe's asin errs 4e-4 rad).
        float sine = clamp(LightRadius / distance, 0.0, 1.0), cosine = sqrt(1.0 - sine * sine), tangent = sine / max(cosine, 1e-6);
        float solid = flat_lamp ? min(flat_light_area() * max(-dot(c, LightFrame[2]), 0.0) / (distance * distance), 6.2831853)
                                : 2.0 * pi * sine * sine / (1.0 + cosine);
        int points = flat_lamp ? 34 : 16;
        float seen_power = film_points_lobe_power(power, solid, points);
        float mass = 2.0 * pi / (seen_power + 1.0) * total / float(samples);
        const float golden = pi * (3.0 - sqrt(5.0));
        int j = 0;
        do {
            vec3 l;
            float amount;  // L ΔΩ of the point
            if (flat_lamp) {
                vec3 d = flat_light_point(j, ivec2(34, 21)) - position;
                float r2 = max(dot(d, d), 1e-24);
                l = d * inversesqrt(r2);
                amount = LightRadiance * flat_light_area() * max(-dot(l, LightFrame[2]), 0.0) / r2 / 34.0;
            } else {
                float radius = sqrt((float(j) + 0.5) / 16.0) * tangent, angle = golden * float(j);  // equal areas of the tangent plane
                l = normalize(c + radius * (cos(angle) * cx + sin(angle) * cy));
                amount = 2.0 / (1.0 + cosine) / 16.0;  // a sphere of unit irradiance: L = 1 / (π sin²β)
            }
            if (dot(n, l) <= 0.0) continue;
            float w = pi * amount * phong_lobe_by_chord(r, l, seen_power) / mass, c_h = clamp(dot(v, normalize(v + l)), 0.0, 1.0);
            vec4 at = film_stratum_of(c_h, edges, soft);
            strata.lamp += at * w;
            light += at * w;
            light_c += at * (w * c_h);
            light_c2 += at * (w * c_h * c_h);
        } while (++j < points);
    }
    // Each stratum's angle weighted by its light (one without light keeps the middle of its edges: its
    // angle does not matter then but for a lamp's image).
    vec4 lit = vec4(greaterThan(light, vec4(0.0))), safe = max(light, vec4(1e-30));
    vec4 middle = vec4(edges.x - 0.5 * seen.y, 0.5 * (edges.x + edges.y), 0.5 * (edges.y + edges.z), edges.z + 0.5 * seen.y);
    strata.cosine = clamp(mix(middle, light_c / safe, lit), 0.0, 1.0);
    strata.spread = lit * sqrt(max(light_c2 / safe - strata.cosine * strata.cosine, 0.0));
    return strata;
}
