// glslang as a library: its process-wide initialisation and its preprocessor, which legacy
// effects need before their effect level can be read (the NVIDIA library declares textures and
// samplers through macros).
#pragma once
#include <string>

#include "effect/effect.hpp"

namespace fxview::legacy {

// glslang::InitializeProcess once per process (glslang's own requirement; thread-safe).
void ensure_glslang_process();

// Macros that make Cg's own types and functions HLSL (fixed, samplerRECT, texRECT, ...), given to
// the preprocessor as a preamble so that line numbers stay those of the file.
const char* cg_shims();

// The effect's expanded text (includes already in) through glslang's HLSL preprocessor: macros
// expanded, conditionals resolved, comments gone, every line where it was. EffectError at
// file:line for a preprocessor error.
std::string preprocess_legacy(const effect::Effect& effect);

}  // namespace fxview::legacy
