// DXSAS 0.86 pass scripts as FX Composer ran them, the part fxview's passes can express:
// RenderColorTarget0..3 (empty: the frame), ClearSetColor/ClearSetDepth (a parameter's value),
// Clear=Color|Depth, Draw=Geometry|Buffer. Other commands are warned about once.
#pragma once
#include <string>
#include <vector>

#include "effect/effect.hpp"

namespace fxview::legacy {

void apply_pass_script(effect::Pass& pass, const std::vector<effect::Annotation>& annotations, const effect::Effect& effect,
                       std::vector<std::string>& warnings);

}  // namespace fxview::legacy
