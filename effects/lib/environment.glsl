// Image-based lighting from the scene's environment (`--environment`, the viewer's Scene tab): the
// tables the viewer makes (docs/effect-format.md, "Environment lighting"; black, with
// FxEnvironmentIntensity 0, without an environment). environment_light.glsl lights any BRDF with them,
// environment_pbr.glsl has the split sum of the metallic-roughness model.
#pragma once

uniform mat3 FxEnvironmentRotation : ENVIRONMENTROTATION;
uniform float FxEnvironmentIntensity : ENVIRONMENTINTENSITY;
texture FxEnvironmentSpecularTexture < string ResourceName = "environment:specular"; string ResourceType = "CUBE"; >;
uniform samplerCube FxEnvironmentSpecular = sampler_state { Texture = <FxEnvironmentSpecularTexture>; MinFilter = LinearMipmapNearest; MagFilter = Linear; };
texture FxEnvironmentIrradianceTexture < string ResourceName = "environment:irradiance"; >;
uniform sampler2D FxEnvironmentIrradiance = sampler_state { Texture = <FxEnvironmentIrradianceTexture>; MinFilter = Nearest; MagFilter = Nearest; };
texture FxEnvironmentDfgTexture < string ResourceName = "environment:dfg"; >;
uniform sampler2D FxEnvironmentDfg = sampler_state { Texture = <FxEnvironmentDfgTexture>; MinFilter = Linear; MagFilter = Linear; AddressU = Clamp; AddressV = Clamp; };

// The shading normal bent towards the eye where interpolation turned it away (n·v <= 0 at a
// silhouette), so that the environment's light does not leave black dots against the background:
// n·v becomes at least 0.01.
vec3 environment_facing_normal(vec3 n, vec3 v) {
    float nv = dot(n, v);
    return nv >= 0.01 ? n : normalize(n + (0.01 - nv) * v);
}

// The map's radiance towards `world_direction` (without the disc lights), blurred by a GGX lobe of
// `roughness` (prefiltered level k for roughness (k / (levels - 1))², linear between two).
vec3 environment_radiance(vec3 world_direction, float roughness) {
    vec3 d = FxEnvironmentRotation * world_direction;
    float last = float(textureQueryLevels(FxEnvironmentSpecular) - 1);
    float lod = sqrt(clamp(roughness, 0.0, 1.0)) * last;
    float l0 = floor(lod);
    vec3 a = textureLod(FxEnvironmentSpecular, d, l0).rgb;
    vec3 b = textureLod(FxEnvironmentSpecular, d, min(l0 + 1.0, last)).rgb;
    return mix(a, b, lod - l0) * FxEnvironmentIntensity;
}

// The prefiltered roughness whose lobe (about 4 pi alpha^2 of solid angle) covers `share` steradians:
// where a filtered importance sample reads the map.
float environment_share_roughness(float share) { return sqrt(clamp(sqrt(share / (4.0 * 3.14159265358979323846)), 0.0, 1.0)); }

// What a white Lambertian surface with normal `world_normal` reflects of the map without its disc
// lights: irradiance / pi from order-2 SH.
vec3 environment_map_irradiance(vec3 world_normal) {
    vec3 d = FxEnvironmentRotation * world_normal;
    float basis[9] = float[9](0.282095, 0.488603 * d.y, 0.488603 * d.z, 0.488603 * d.x, 1.092548 * d.x * d.y, 1.092548 * d.y * d.z,
                              0.315392 * (3.0 * d.z * d.z - 1.0), 1.092548 * d.x * d.z, 0.546274 * (d.x * d.x - d.y * d.y));
    vec3 sum = vec3(0.0);
    for (int k = 0; k < 9; ++k) sum += basis[k] * texelFetch(FxEnvironmentIrradiance, ivec2(k, 0), 0).rgb;
    return max(sum, vec3(0.0)) * FxEnvironmentIntensity;
}

// The disc lights (the sky's sun, a lamp or sun taken out of an image), at most four: kept out of the
// prefiltered map and the SH and shaded in closed form. Disc k's world direction and angular radius;
// returns its radiance x solid angle (zero: no disc k).
const int kFxEnvironmentDiscs = 4;
vec3 environment_disc(int k, out vec3 world_direction, out float angular_radius) {
    vec4 a = texelFetch(FxEnvironmentIrradiance, ivec2(9 + 2 * k, 0), 0);
    world_direction = transpose(FxEnvironmentRotation) * a.xyz;  // a rotation: its inverse
    angular_radius = a.w;
    return texelFetch(FxEnvironmentIrradiance, ivec2(10 + 2 * k, 0), 0).rgb * FxEnvironmentIntensity;
}

// The direction nearest to `towards` of the disc of `angular_radius` about `centre`.
vec3 environment_disc_nearest(vec3 centre, float angular_radius, vec3 towards) {
    float c = clamp(dot(centre, towards), -1.0, 1.0);
    if (c >= cos(angular_radius)) return towards;
    vec3 side = towards - c * centre;
    float length_side = length(side);
    if (length_side < 1e-8) return centre;  // towards the opposite way: any edge point is as near
    return cos(angular_radius) * centre + sin(angular_radius) * side / length_side;
}

// GGX width alpha widened for a disc of `angular_radius` seen through a BRDF evaluated at its centre:
// the lobe's mean over the disc is the peak of a lobe sqrt(alpha² + (radius/2)²) wide.
float environment_disc_alpha(float alpha, float angular_radius) { return sqrt(alpha * alpha + 0.25 * angular_radius * angular_radius); }

// What a white Lambertian surface with normal `world_normal` reflects: irradiance / pi (order-2 SH,
// the discs in closed form: the SH would ring about them).
vec3 environment_irradiance(vec3 world_normal) {
    vec3 sum = environment_map_irradiance(world_normal);
    for (int k = 0; k < kFxEnvironmentDiscs; ++k) {
        vec3 direction;
        float radius;
        vec3 power = environment_disc(k, direction, radius);
        sum += max(dot(world_normal, direction), 0.0) * power / 3.14159265358979323846;
    }
    return sum;
}

// The split sum's (A, B): single-scattering GGX reflects F0 A + B of uniform light; and G, with which
// the diffuse part (1 - F(v·h)) base/π reflects (1 - F0)(1 - G) base of uniform light.
// Texel centres hold n·v and roughness 0, 1/(size-1), ..., 1.
vec3 environment_dfg(float nv, float roughness) {
    vec2 size = vec2(textureSize(FxEnvironmentDfg, 0));
    return texture(FxEnvironmentDfg, (clamp(vec2(nv, roughness), 0.0, 1.0) * (size - 1.0) + 0.5) / size).xyz;
}

