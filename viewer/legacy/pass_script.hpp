// DXSAS 0.86 pass scripts as FX Composer ran them, the part fxview's passes can express:
// RenderColorTarget0..3 (empty: the frame), ClearSetColor/ClearSetDepth (a parameter's value),
// Clear=Color|Depth, Draw=Geometry|Buffer. Other commands are warned about once.
#pragma once
#include <string>
#include <vector>

#include "effect/effect.hpp"

namespace fxview::legacy {

// Returns whether the script chose the pass's render targets (else the technique script's apply).
bool apply_pass_script(effect::Pass& pass, const std::vector<effect::Annotation>& annotations, const effect::Effect& effect,
                       std::vector<std::string>& warnings);

// The technique's Script: passes in the order of its Pass= commands, LoopByCount=N|PARAM ... LoopEnd
// repeated (at most 256 passes in all), RenderColorTarget/Clear commands for the passes that follow
// unless their own script sets targets, ScriptExternal=color as a pass drawing the scene's objects
// with fxview's plain shader. Without Pass= commands the declared order stays.
void apply_technique_script(effect::Technique& technique, const std::vector<bool>& pass_sets_targets, const effect::Effect& effect,
                            std::vector<std::string>& warnings);

}  // namespace fxview::legacy
