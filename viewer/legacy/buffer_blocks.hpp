// Cg 3 uniform buffers, `uniform struct [NAME] { members } VAR : BUFFER[n];` (an application fills
// them through cgSetBuffer; no effect-file tool did): rewritten before the effect level is read into
// what HLSL compiles and fxview can show, line for line:
//   TYPE VAR_member [: SEMANTIC];            on each member's own line
//   struct __fxbuffer_VAR { members }; static __fxbuffer_VAR VAR = { VAR_member, ... };   on the last
// so every member is a parameter of its own (VAR_member, its semantic kept: the scene supplies
// WorldViewProjection and kin) and the code's VAR.member reads it unchanged.
#pragma once
#include <string>
#include <vector>

#include "effect/source_map.hpp"

namespace fxview::legacy {

// Returns the text with each buffer block rewritten; adds a warning "file:line: warning: ..." per
// block to `warnings`. Throws EffectError at file:line for a block it cannot read (nested struct
// definitions, members with initialisers or annotations, no members, no BUFFER[n];).
std::string rewrite_buffer_blocks(const std::string& text, const effect::SourceMap& sources, std::vector<std::string>& warnings);

}  // namespace fxview::legacy
