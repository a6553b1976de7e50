// References for effects/debug.fx: the debug views of seed 002 ch. 4.1 (eq. 55) and Plain.
#pragma once
#include <map>
#include <string>

#include "reference/reference.hpp"

namespace fxview::reference {

std::map<std::string, Reference> debug_references();

}  // namespace fxview::reference
