// The scene environment's spectral form (lighting::SpectralForm; render/environment_maps.hpp):
// L(d, λ) = Σ_k w_k(d) S_k(λ), three spectra of luminance 1 and their weights per direction, the disc
// lights (the sun) drawn in. The built-in sky has one (its dome in 12000 K daylight, its sun in
// daylight of the sky's CCT, the ground lit by both) and the studio (all in D65); elsewhere
// spectral_environment() is false and a technique stays lit by its light spectrum (and fxview says so).
#pragma once

uniform mat3 FxSpectralEnvironmentRotation : ENVIRONMENTROTATION;
uniform float FxSpectralEnvironmentIntensity : ENVIRONMENTINTENSITY;
texture FxSpectralWeightsTexture < string ResourceName = "environment:spectral-weights"; string ResourceType = "CUBE"; >;
uniform samplerCube FxSpectralWeights = sampler_state { Texture = <FxSpectralWeightsTexture>; MinFilter = Linear; MagFilter = Linear; };
texture FxSpectralSpectraTexture < string ResourceName = "environment:spectra"; >;
uniform sampler2D FxSpectralSpectra = sampler_state { Texture = <FxSpectralSpectraTexture>; MinFilter = Nearest; MagFilter = Nearest; };

bool spectral_environment() { return texelFetch(FxSpectralSpectra, ivec2(0, 0), 0).a > 0.0 && FxSpectralEnvironmentIntensity > 0.0; }

// The weights of the three spectra arriving from `world_direction` (towards the environment).
vec3 spectral_environment_weights(vec3 world_direction) {
    return textureLod(FxSpectralWeights, FxSpectralEnvironmentRotation * world_direction, 0.0).rgb * FxSpectralEnvironmentIntensity;
}

// The three spectra at `nm` (360-830).
vec3 spectral_environment_spectra(int nm) { return texelFetch(FxSpectralSpectra, ivec2(nm - 360, 0), 0).rgb; }

// The radiance at `nm` (360-830) of light with those weights.
float spectral_environment_radiance(vec3 weights, int nm) { return dot(weights, spectral_environment_spectra(nm)); }
