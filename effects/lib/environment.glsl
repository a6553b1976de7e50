// Image-based lighting from the scene's environment (`--environment`, the viewer's Scene tab): the
// split-sum approximation with multiple-scattering energy compensation for the metallic-roughness
// GGX model of brdf.glsl. The tables come from the viewer (docs/effect-format.md, "Environment
// lighting"); without an environment they are black and FxEnvironmentIntensity is 0.
// Assumptions of the split sum (their error is what `fxview compare --ground-truth` measures): the
// radiance is prefiltered as if n = v = r, and the lobe's shape and its Fresnel-weighted integral
// are taken apart.
#pragma once

uniform mat3 FxEnvironmentRotation : ENVIRONMENTROTATION;
uniform float FxEnvironmentIntensity : ENVIRONMENTINTENSITY;
texture FxEnvironmentSpecularTexture < string ResourceName = "environment:specular"; string ResourceType = "CUBE"; >;
uniform samplerCube FxEnvironmentSpecular = sampler_state { Texture = <FxEnvironmentSpecularTexture>; MinFilter = LinearMipmapNearest; MagFilter = Linear; };
texture FxEnvironmentIrradianceTexture < string ResourceName = "environment:irradiance"; >;
uniform sampler2D FxEnvironmentIrradiance = sampler_state { Texture = <FxEnvironmentIrradianceTexture>; MinFilter = Nearest; MagFilter = Nearest; };
texture FxEnvironmentDfgTexture < string ResourceName = "environment:dfg"; >;
uniform sampler2D FxEnvironmentDfg = sampler_state { Texture = <FxEnvironmentDfgTexture>; MinFilter = Linear; MagFilter = Linear; AddressU = Clamp; AddressV = Clamp; };

uniform bool EnergyCompensation < string UIName = "Multiple-scattering compensation"; string UIGroup = "Environment";
                                  string UIHelp = "Adds the energy that single-scattering GGX loses on rough surfaces (environment light only)"; > = true;

// The environment's radiance towards `world_direction`, blurred by a GGX lobe of `roughness`
// (prefiltered levels k / (levels - 1), linear between two).
vec3 environment_radiance(vec3 world_direction, float roughness) {
    vec3 d = FxEnvironmentRotation * world_direction;
    float last = float(textureQueryLevels(FxEnvironmentSpecular) - 1);
    float lod = clamp(roughness, 0.0, 1.0) * last;
    float l0 = floor(lod);
    vec3 a = textureLod(FxEnvironmentSpecular, d, l0).rgb;
    vec3 b = textureLod(FxEnvironmentSpecular, d, min(l0 + 1.0, last)).rgb;
    return mix(a, b, lod - l0) * FxEnvironmentIntensity;
}

// What a white Lambertian surface with normal `world_normal` reflects: irradiance / pi (order-2 SH).
vec3 environment_irradiance(vec3 world_normal) {
    vec3 d = FxEnvironmentRotation * world_normal;
    float basis[9] = float[9](0.282095, 0.488603 * d.y, 0.488603 * d.z, 0.488603 * d.x, 1.092548 * d.x * d.y, 1.092548 * d.y * d.z,
                              0.315392 * (3.0 * d.z * d.z - 1.0), 1.092548 * d.x * d.z, 0.546274 * (d.x * d.x - d.y * d.y));
    vec3 sum = vec3(0.0);
    for (int k = 0; k < 9; ++k) sum += basis[k] * texelFetch(FxEnvironmentIrradiance, ivec2(k, 0), 0).rgb;
    return max(sum, vec3(0.0)) * FxEnvironmentIntensity;
}

// The split sum's (A, B): single-scattering GGX reflects F0 A + B of uniform light; and G, with which
// the diffuse part (1 - F(v·h)) base/π reflects (1 - F0)(1 - G) base of uniform light.
vec3 environment_dfg(float nv, float roughness) { return texture(FxEnvironmentDfg, vec2(nv, roughness)).xyz; }

// Where a GGX lobe of `roughness` gathers most light: the mirror direction for smooth surfaces, turning
// towards the normal as they roughen (Lagarde & de Rousiers 2014, Frostbite), since the prefiltered
// lobes are centred as if n = v.
vec3 specular_dominant_direction(Frame f, float roughness) {
    float s = (1.0 - roughness) * (sqrt(1.0 - roughness) + roughness);
    return normalize(mix(f.n, reflect(-f.v, f.n), s));
}

// Metallic-roughness GGX (brdf.glsl's metallic_roughness) lit by the environment: the specular split
// sum scaled by 1 + F0 (1/E - 1) for multiple scattering (E = A + B, Fdez-Agüera 2019), and the
// diffuse part by what it reflects of uniform light, (1 - F0)(1 - G). Black where the eye is below the surface.
vec3 metallic_roughness_environment(Frame f, vec3 base, float metallic, float roughness) {
    if (f.nv <= 0.0) return vec3(0.0);
    vec3 f0 = mix(vec3(0.04), base, metallic);
    vec3 ab = environment_dfg(f.nv, roughness);
    vec3 compensation = EnergyCompensation ? 1.0 + f0 * (1.0 / max(ab.x + ab.y, 1e-4) - 1.0) : vec3(1.0);
    vec3 specular = (f0 * ab.x + ab.y) * compensation * environment_radiance(specular_dominant_direction(f, roughness), roughness);
    vec3 diffuse = (1.0 - f0) * (1.0 - ab.z) * (1.0 - metallic) * base * environment_irradiance(f.n);
    return specular + diffuse;
}
