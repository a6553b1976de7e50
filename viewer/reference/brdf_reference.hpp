// References for effects/brdf/analytic.fx (DOMAIN.md §7).
#pragma once
#include <map>
#include <string>

#include "reference/reference.hpp"

namespace fxview::reference {

std::map<std::string, Reference> brdf_references();

}  // namespace fxview::reference
