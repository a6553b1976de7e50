// References for effects/brdf/measured.fx: the measured BRDF looked up by angle (through the CPU
// sampler's trilinear 3D filtering), the fitted model, and their difference.
#pragma once
#include <map>
#include <string>

#include "reference/reference.hpp"

namespace fxview::reference {

std::map<std::string, Reference> measured_references();

}  // namespace fxview::reference
