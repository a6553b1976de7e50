// The scene environment's spectral form (environment_spectral.glsl) gathered by a Lambertian surface
// and by the thesis' Phong and Blinn lobes, as weights of its three spectra: L_o(λ) = Σ_k w_k S_k(λ).
// The lobes are taken as the BRDFs their point-light formulas imply: with a lamp of Brightness B
// standing for irradiance π B, ks (r·v)^p B is f cos θ_i π B, so f cos θ_i = ks (r·v)^p / π (Blinn:
// (n·h)^p). Under uniform radiance 1 a head-on Phong lobe then reflects ks · 2 / (p + 1).
#pragma once
#include "environment_spectral.glsl"

texture FxSpectralIrradianceTexture < string ResourceName = "environment:spectral-irradiance"; string ResourceType = "CUBE"; >;
uniform samplerCube FxSpectralIrradiance = sampler_state { Texture = <FxSpectralIrradianceTexture>; MinFilter = Linear; MagFilter = Linear; };
// The weights without the disc lights, read at whole levels of their box-filtered chain (two levels
// mixed by hand, as the CPU reference does), and the discs apart: a small bright sun read through 32
// lobe directions would show as their pattern, a spray of sparks.
texture FxSpectralLobeWeightsTexture < string ResourceName = "environment:spectral-lobe-weights"; string ResourceType = "CUBE"; >;
uniform samplerCube FxSpectralWeightLevels = sampler_state { Texture = <FxSpectralLobeWeightsTexture>; MinFilter = LinearMipmapNearest; MagFilter = Linear; };
texture FxSpectralDiscsTexture < string ResourceName = "environment:spectral-discs"; >;
uniform sampler2D FxSpectralDiscs = sampler_state { Texture = <FxSpectralDiscsTexture>; MinFilter = Nearest; MagFilter = Nearest; };
const int kSpectralDiscs = 4, kSpectralDiscPoints = 16;
texture FxLobeMassTexture < string ResourceName = "environment:lobe-mass"; >;
uniform sampler2D FxLobeMass = sampler_state { Texture = <FxLobeMassTexture>; MinFilter = Linear; MagFilter = Linear; AddressU = Clamp; AddressV = Clamp; };

// (1/π) ∫ lobe over the directions above the surface: x Phong, y Blinn (tabulated per n·v and log2 p / 8
// in units of the whole Phong lobe, 2 / (p + 1), which interpolate well across p).
vec2 spectral_lobe_mass(float nv, float power) {
    float size = float(textureSize(FxLobeMass, 0).x);
    vec2 at = vec2(clamp(nv, 0.0, 1.0), clamp(log2(max(power, 1.0)) / 8.0, 0.0, 1.0));
    return textureLod(FxLobeMass, (at * (size - 1.0) + 0.5) / size, 0.0).xy * (2.0 / (power + 1.0));
}

// Directions per lobe: wide lobes need more to see a studio's soft boxes evenly (measured against
// the ground truth under the studio, Blinn at power 1: mean CIEDE2000 0.89 with 128, 0.48 with 256,
// 0.36 with 1024; the sample pattern shows as faint blotches below that).
int spectral_lobe_samples(float power) { return power >= 64.0 ? 32 : power >= 8.0 ? 64 : 256; }

// The weights E(n)/π: what a white Lambertian surface facing world normal n reflects.
vec3 spectral_environment_irradiance(vec3 n) {
    return textureLod(FxSpectralIrradiance, FxSpectralEnvironmentRotation * n, 0.0).rgb * FxSpectralEnvironmentIntensity;
}

// The weights averaged over the cone a sample stands for (`share` steradians): the level whose texels
// cover it, one level coarser (Křivánek & Colbert 2008); none coarser than 8² a face (on smaller faces
// every lookup touches a cube corner, whose filtering GL leaves to the implementation).
vec3 spectral_environment_filtered(vec3 world_direction, float share) {
    float size = float(textureSize(FxSpectralWeightLevels, 0).x);
    float last = min(float(textureQueryLevels(FxSpectralWeightLevels) - 1), max(log2(size / 8.0), 0.0));
    float lod = clamp(0.5 * log2(share * 6.0 * size * size / (4.0 * 3.14159265358979323846)) + 1.0, 0.0, last);
    float low = floor(lod);
    vec3 d = FxSpectralEnvironmentRotation * world_direction;
    vec3 a = textureLod(FxSpectralWeightLevels, d, low).rgb, b = textureLod(FxSpectralWeightLevels, d, min(low + 1.0, last)).rgb;
    return mix(a, b, lod - low) * FxSpectralEnvironmentIntensity;
}

// A tangent frame about unit `axis` (Duff et al. 2017).
void spectral_frame(vec3 axis, out vec3 x, out vec3 y) {
    float s = axis.z >= 0.0 ? 1.0 : -1.0, a = -1.0 / (s + axis.z), b = axis.x * axis.y * a;
    x = vec3(1.0 + s * axis.x * axis.x * a, s * b, -s * axis.x);
    y = vec3(b, s + axis.y * axis.y * a, -axis.y);
}

// The lobe towards l: (r·v)^p (Phong) or (n·h)^p (Blinn), zero below the surface.
float spectral_lobe(vec3 n, vec3 v, vec3 l, bool blinn, float power) {
    if (dot(n, l) <= 0.0) return 0.0;
    return pow(max(blinn ? dot(n, normalize(l + v)) : dot(reflect(-v, n), l), 0.0), power);
}

// (1/π) ∫ lobe(l) L(l) dl over the disc lights, as weights: 16 points of equal area over each disc (a
// sunflower spiral), enough for the lobes' widths (4° and more at power 256) against a 1.5° sun.
vec3 spectral_disc_highlight(vec3 n, vec3 v, bool blinn, float power) {
    n = FxSpectralEnvironmentRotation * n;  // the discs are in environment space
    v = FxSpectralEnvironmentRotation * v;
    const float golden = 3.14159265358979323846 * (3.0 - sqrt(5.0));
    vec3 sum = vec3(0.0);
    for (int k = 0; k < kSpectralDiscs; ++k) {
        vec4 place = texelFetch(FxSpectralDiscs, ivec2(2 * k, 0), 0), light = texelFetch(FxSpectralDiscs, ivec2(2 * k + 1, 0), 0);
        if (!(light.a > 0.0)) continue;
        vec3 x, y;
        spectral_frame(place.xyz, x, y);
        float lobe = 0.0;
        for (int j = 0; j < kSpectralDiscPoints; ++j) {
            float r = sqrt((float(j) + 0.5) / float(kSpectralDiscPoints)) * place.w, angle = golden * float(j);
            lobe += spectral_lobe(n, v, normalize(place.xyz + tan(r) * (cos(angle) * x + sin(angle) * y)), blinn, power);
        }
        sum += light.rgb * (light.a * lobe / float(kSpectralDiscPoints));
    }
    return sum / 3.14159265358979323846 * FxSpectralEnvironmentIntensity;
}

// (1/π) ∫ lobe(l) L(l) dl over the directions above the surface, as weights: the lobe's mass above
// the surface (tabulated) times the mean weights under it, by filtered importance sampling with
// spectral_lobe_samples() directions distributed as the lobe (Phong: l about the mirror direction of v; Blinn: h about n,
// l = v reflected about h, each counted by 4 v·h), plus the disc lights. `blinn` picks the lobe,
// `power` is its exponent.
vec3 spectral_environment_highlight(vec3 n, vec3 v, bool blinn, float power) {
    const float pi = 3.14159265358979323846;
    vec3 axis = blinn ? n : reflect(-v, n), x, y;
    spectral_frame(axis, x, y);
    vec3 sum = vec3(0.0);
    float total = 0.0;
    int count = spectral_lobe_samples(power);
    for (int i = 0; i < count; ++i) {
        float u1 = (float(i) + 0.5) / float(count), u2 = float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10;
        float c = pow(1.0 - u1, 1.0 / (power + 1.0)), sine = sqrt(max(0.0, 1.0 - c * c)), phi = 2.0 * pi * u2;
        vec3 direction = sine * cos(phi) * x + sine * sin(phi) * y + c * axis;
        float density = (power + 1.0) / (2.0 * pi) * pow(c, power), weight = 1.0;
        vec3 l = direction;
        if (blinn) {
            float vh = dot(v, direction);
            if (vh <= 0.0) continue;
            l = 2.0 * vh * direction - v;
            density /= 4.0 * vh;
            weight = 4.0 * vh;
        }
        if (dot(n, l) <= 0.0 || !(density > 0.0)) continue;
        sum += weight * spectral_environment_filtered(l, 1.0 / (float(count) * density));
        total += weight;
    }
    vec2 mass = spectral_lobe_mass(dot(n, v), power);
    return (total > 0.0 ? sum / total * (blinn ? mass.y : mass.x) : vec3(0.0)) + spectral_disc_highlight(n, v, blinn, power);
}
