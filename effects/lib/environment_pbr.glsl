// The metallic-roughness model of brdf.glsl lit by the environment: the split-sum approximation with
// multiple-scattering energy compensation. Assumptions of the split sum (their error is what
// `fxview compare --ground-truth` measures): the radiance is prefiltered as if n = v = r, and the
// lobe's shape and its Fresnel-weighted integral are taken apart.
#pragma once
#include "brdf.glsl"
#include "environment.glsl"

uniform bool LobeSampling < string UIName = "Sampled specular lobe"; string UIGroup = "Environment";
                            string UIHelp = "Reads the environment over the specular lobe as it leaves this surface (16 filtered reads; closer to the true integral, about 5x the cost on a CPU renderer). Off: one read in the lobe's main direction (the classic split sum)"; > = true;
uniform bool EnergyCompensation < string UIName = "Multiple-scattering compensation"; string UIGroup = "Environment";
                                  string UIHelp = "Adds the energy that single-scattering GGX loses on rough surfaces (environment light only)"; > = true;

// The radiance the specular lobe of `roughness` gathers for this eye, the map's part of the split sum:
// 16 GGX normals about n reflected about v (not n = v, which the prefiltered map alone assumes and
// which stretches reflections wrongly at grazing angles), each direction weighted by what masking and
// Fresnel give it (f (n·l) / pdf without the lobe's scale) and read from the prefiltered level whose
// lobe covers its share of the sphere (filtered importance sampling, Křivánek & Colbert 2008). The
// weights are normalised, so the energy stays the DFG table's.
const int kFxLobeSamples = 16;
vec3 environment_lobe_radiance(vec3 n, vec3 v, vec3 f0, float roughness) {
    float alpha = max(roughness * roughness, 1e-4), a2 = alpha * alpha, nv = max(dot(n, v), 1e-4);
    // An orthonormal frame from n alone (Duff et al. 2017): the lobe is isotropic.
    float s = n.z >= 0.0 ? 1.0 : -1.0, a = -1.0 / (s + n.z), b = n.x * n.y * a;
    vec3 x = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x), y = vec3(b, s + n.y * n.y * a, -n.y);
    vec3 sum = vec3(0.0), total = vec3(0.0);
    for (int i = 0; i < kFxLobeSamples; ++i) {
        float u1 = (float(i) + 0.5) / float(kFxLobeSamples), u2 = float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10;
        float nh = sqrt((1.0 - u1) / (1.0 + (a2 - 1.0) * u1)), sin_h = sqrt(max(0.0, 1.0 - nh * nh)), phi = 2.0 * kPi * u2;
        vec3 h = sin_h * cos(phi) * x + sin_h * sin(phi) * y + nh * n;
        float vh = dot(v, h);
        vec3 l = 2.0 * vh * h - v;
        float nl = dot(n, l);
        if (nl <= 0.0 || vh <= 0.0) continue;
        float pdf = ggx(nh, alpha) * nh / (4.0 * vh);
        vec3 weight = fresnel_schlick(f0, vh) * (smith_ggx_correlated(nl, nv, alpha) * vh / nh);
        sum += weight * environment_radiance(l, environment_share_roughness(1.0 / (float(kFxLobeSamples) * pdf)));
        total += weight;
    }
    return total.r + total.g + total.b > 0.0 ? sum / max(total, vec3(1e-30)) : environment_radiance(reflect(-v, n), roughness);
}

// Where a GGX lobe of `roughness` gathers most light: the mirror direction turned towards the normal
// as the surface roughens (Lagarde & de Rousiers 2014, Frostbite).
vec3 specular_dominant_direction(vec3 n, vec3 v, float roughness) {
    float s = (1.0 - roughness) * (sqrt(1.0 - roughness) + roughness);
    return normalize(mix(n, reflect(-v, n), s));
}

// The map's part of the split sum: the sampled lobe up to roughness 0.5, blending into the
// prefiltered level at the dominant direction by roughness 1, where the 16 samples' own footprints
// blur the lobe twice (measured against the ground truth, docs/brdf.md).
vec3 environment_specular_radiance(vec3 n, vec3 v, vec3 f0, float roughness) {
    float t = LobeSampling ? clamp(2.0 * roughness - 1.0, 0.0, 1.0) : 1.0;
    vec3 lobe = t < 1.0 ? environment_lobe_radiance(n, v, f0, roughness) : vec3(0.0);
    vec3 dominant = t > 0.0 ? environment_radiance(specular_dominant_direction(n, v, roughness), roughness) : vec3(0.0);
    return mix(lobe, dominant, t);
}

// The disc lights through the BRDF at their centres, as under the rest of the environment with
// height-correlated masking (the DFG table's) and the specular part scaled by `compensation`; its GGX
// lobe widened by the disc (environment_disc_alpha: a mirror shows the disc, a rough lobe is unchanged).
vec3 metallic_roughness_discs(Frame f, vec3 base, float metallic, float roughness, vec3 compensation) {
    vec3 sum = vec3(0.0);
    vec3 f0 = mix(vec3(0.04), base, metallic);
    float alpha = roughness * roughness;
    for (int k = 0; k < kFxEnvironmentDiscs; ++k) {
        vec3 centre;
        float radius;
        vec3 power = environment_disc(k, centre, radius);
        Frame g = frame_of(centre, f.v, f.n, f.t);
        if (!(power.r + power.g + power.b > 0.0) || g.nl <= 0.0) continue;
        vec3 F = fresnel_schlick(f0, max(g.vh, 0.0));
        vec3 diffuse = (1.0 - F) * (1.0 - metallic) * base / kPi;
        vec3 specular = ggx(g.nh, environment_disc_alpha(alpha, radius)) * smith_ggx_correlated(g.nl, g.nv, alpha) * F / (4.0 * g.nl * g.nv);
        sum += (diffuse + specular * compensation) * g.nl * power;
    }
    return sum;
}

// Metallic-roughness GGX (brdf.glsl's metallic_roughness) lit by the environment: the specular split
// sum scaled by 1 + F0 (1/E - 1) for multiple scattering (E = A + B, Fdez-Agüera 2019), and the
// diffuse part by what it reflects of uniform light, (1 - F0)(1 - G); the disc lights in closed form
// (metallic_roughness_discs); at silhouettes with the normal bent towards the eye
// (environment_facing_normal).
vec3 metallic_roughness_environment(Frame f, vec3 base, float metallic, float roughness) {
    vec3 n = environment_facing_normal(f.n, f.v);
    f.n = n;
    f.nv = dot(n, f.v);
    vec3 f0 = mix(vec3(0.04), base, metallic);
    vec3 ab = environment_dfg(f.nv, roughness);
    vec3 compensation = EnergyCompensation ? 1.0 + f0 * (1.0 / max(ab.x + ab.y, 1e-4) - 1.0) : vec3(1.0);
    vec3 specular = (f0 * ab.x + ab.y) * compensation * environment_specular_radiance(f.n, f.v, f0, roughness);
    vec3 diffuse = (1.0 - f0) * (1.0 - ab.z) * (1.0 - metallic) * base * environment_map_irradiance(f.n);
    return specular + diffuse + metallic_roughness_discs(f, base, metallic, roughness, compensation);
}
