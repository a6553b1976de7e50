// Cg 3 uniform buffers, `uniform struct [NAME] { members } VAR : BUFFER[n];` (an application fills
// them through cgSetBuffer; no effect-file tool did): rewritten before the effect level is read into
// what HLSL compiles and fxview can show, line for line:
//   struct __fxbuffer_VAR { members };  TYPE VAR_member [: SEMANTIC]; ...
//   static __fxbuffer_VAR VAR = { VAR_member, ... };
// so every member is a parameter of its own (VAR_member, its semantic kept: the scene supplies
// WorldViewProjection and kin) and the code's VAR.member reads it unchanged.
#pragma once
#include <string>
#include <vector>

#include "effect/source_map.hpp"

namespace fxview::legacy {

// Returns the text with each buffer block rewritten; adds a warning "file:line: warning: ..." per
// block to `warnings`. Blocks it cannot read (nested braces, no members) are left for the parser,
// which reports them at their line.
std::string rewrite_buffer_blocks(const std::string& text, const effect::SourceMap& sources, std::vector<std::string>& warnings);

}  // namespace fxview::legacy
