// The metallic-roughness model of brdf.glsl lit by the environment: the split-sum approximation with
// multiple-scattering energy compensation. Assumptions of the split sum (their error is what
// `fxview compare --ground-truth` measures): the radiance is prefiltered as if n = v = r, and the
// lobe's shape and its Fresnel-weighted integral are taken apart.
#pragma once
#include "brdf.glsl"
#include "environment.glsl"

uniform bool EnergyCompensation < string UIName = "Multiple-scattering compensation"; string UIGroup = "Environment";
                                  string UIHelp = "Adds the energy that single-scattering GGX loses on rough surfaces (environment light only)"; > = true;

// Where a GGX lobe of `roughness` gathers most light: the mirror direction for smooth surfaces, turning
// towards the normal as they roughen (Lagarde & de Rousiers 2014, Frostbite), since the prefiltered
// lobes are centred as if n = v.
vec3 specular_dominant_direction(Frame f, float roughness) {
    float s = (1.0 - roughness) * (sqrt(1.0 - roughness) + roughness);
    return normalize(mix(f.n, reflect(-f.v, f.n), s));
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
    vec3 specular = (f0 * ab.x + ab.y) * compensation * environment_radiance(specular_dominant_direction(f, roughness), roughness);
    vec3 diffuse = (1.0 - f0) * (1.0 - ab.z) * (1.0 - metallic) * base * environment_map_irradiance(f.n);
    return specular + diffuse + metallic_roughness_discs(f, base, metallic, roughness, compensation);
}
