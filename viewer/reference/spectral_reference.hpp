// References for effects/spectral/wavelength.fx (seed 002 Tables 3 and 4).
#pragma once
#include <map>
#include <string>

#include "reference/reference.hpp"

namespace fxview::reference {

std::map<std::string, Reference> spectral_references();

}  // namespace fxview::reference
