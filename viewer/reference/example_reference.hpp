// References for effects/examples/textured.fx.
#pragma once
#include <map>
#include <string>

#include "reference/reference.hpp"

namespace fxview::reference {

std::map<std::string, Reference> example_references();

}  // namespace fxview::reference
