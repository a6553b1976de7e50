// Render and sampler states of legacy effects in both spellings: DirectX 9 (ZEnable, CullMode,
// AlphaBlendEnable, SrcBlend, AddressU, MipFilter, ...) and CgFX (DepthTestEnable, BlendFunc =
// int2(...), WrapS, ...). States that core GL cannot honour (fixed-function lighting, fog, alpha
// test) and unknown ones are warned about once each, never fatal: a legacy file should open.
#pragma once
#include <set>
#include <string>
#include <vector>

#include "effect/effect.hpp"
#include "effect/lexer.hpp"

namespace fxview::legacy {

void set_legacy_render_state(effect::RenderStates& states, const std::string& name, const std::vector<effect::Token>& value,
                             const effect::SourceLocation& where, std::vector<std::string>& warnings, std::set<std::string>& warned);

void set_legacy_sampler_state(effect::SamplerState& sampler, const std::string& name, const std::string& value,
                              const effect::SourceLocation& where, std::vector<std::string>& warnings, std::set<std::string>& warned);

// DirectX and CgFX texture format names (A8R8G8B8, A16B16G16R16F, RGBA32F, ...) as storage.
effect::TextureStorage storage_from_format(const std::string& format);

}  // namespace fxview::legacy
