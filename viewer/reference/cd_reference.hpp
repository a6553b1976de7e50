// References for effects/spectral/cd.fx (seed 002 ch. 4.5).
#pragma once
#include <map>
#include <string>

#include "reference/reference.hpp"

namespace fxview::reference {

std::map<std::string, Reference> cd_references();

}  // namespace fxview::reference
