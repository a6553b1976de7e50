// Texture and sampler settings from annotations and CgFX sampler_state blocks:
//   ResourceName, ResourceType (1D, 2D, 3D, CUBE), Depth (slices of a 3D image), Format (8, 16F, 32F and the CgFX names),
//   ColorSpace (sRGB, linear), ViewportRatio, Dimensions; Filter (nearest, linear, mipmap),
//   Wrap (repeat, clamp, mirror), MinFilter/MagFilter and WrapS/WrapT/WrapR (AddressU/V/W).
#pragma once
#include <string>
#include <vector>

#include "effect/effect.hpp"

namespace fxview::effect {

// Applies the texture-related annotations; returns whether any of them was present.
bool apply_texture_annotations(TextureResource& texture, const std::vector<Annotation>& annotations);
// Applies the sampler-related annotations (Filter, Wrap, ...).
void apply_sampler_annotations(SamplerState& sampler, const std::vector<Annotation>& annotations);
// One `Name = value;` of a sampler_state block (the texture reference is handled by the parser).
void set_sampler_state(SamplerState& sampler, const std::string& name, const std::string& value, const SourceLocation& where);

}  // namespace fxview::effect
