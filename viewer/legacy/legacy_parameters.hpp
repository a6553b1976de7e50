// The globals of a legacy effect as fxview parameters: Cg/HLSL types as GLSL ones, SAS semantics
// (World, ViewInverse, WorldViewProjection, Position with Object = "PointLight0", Time, ...) as
// the values the scene supplies, annotations as UI hints, defaults in fxview's matrix order, and
// samplers bound to their sampler_state texture.
#pragma once
#include <string>

#include "effect/effect.hpp"
#include "legacy/legacy_source.hpp"

namespace fxview::legacy {

// Adds the parameter (or a warning where its type has no fxview equivalent). Needs
// effect.row_vectors and effect.textures set.
void add_parameter(effect::Effect& effect, const LegacyGlobal& global);

// The fxview semantic a SAS semantic names, or empty for a material semantic (DIFFUSE,
// SPECULARPOWER, ...) whose value the user edits.
std::string scene_semantic(const LegacyGlobal& global);

// float4 -> vec4, half3x3 -> mat3, samplerCUBE -> samplerCube, ...; empty without an equivalent.
std::string glsl_type(const std::string& legacy_type);

}  // namespace fxview::legacy
