// Legacy effects (docs/legacy-effects.md): CgFX files holding Cg and DirectX 9 .fx files holding
// HLSL become an effect::Effect like a native one: parameters keyed by their original names with
// their annotations and SAS semantics, textures and sampler states, techniques whose passes hold
// GLSL 4.5 translated by glslang and SPIRV-Cross.
#pragma once
#include <string>

#include "effect/effect.hpp"

namespace fxview::legacy {

// Whether an effect whose sources are loaded is a legacy one: a .cgfx file, or an .fx file with
// no GLSLShader block whose passes compile functions (`compile PROFILE f(...)`).
bool is_legacy_effect(const effect::Effect& effect);

// Fills `effect` (sources loaded) from its Cg/HLSL. `matrix_convention` ("row", "column" or empty)
// overrides how matrices multiply vectors. EffectError at file:line for what cannot be read; a
// technique whose code does not translate fails alone, when it is compiled.
void load_legacy_effect(effect::Effect& effect, const std::string& matrix_convention);

}  // namespace fxview::legacy
