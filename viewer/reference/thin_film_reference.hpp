// References for effects/spectral/thinfilm.fx (seed 002 ch. 4.4, Tables 5-8).
#pragma once
#include <map>
#include <string>

#include "reference/reference.hpp"

namespace fxview::reference {

std::map<std::string, Reference> thin_film_references();

}  // namespace fxview::reference
