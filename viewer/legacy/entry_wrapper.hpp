// The entry function generated for `compile PROFILE f(arguments)`: glslang compiles one entry
// without uniform parameters, so the wrapper declares f's varying parameters (with their
// semantics) and passes the compile statement's arguments, cast to their types, to f's uniform
// parameters in order, as Cg and the DirectX effect framework do.
#pragma once
#include <string>

#include "legacy/legacy_source.hpp"

namespace fxview::legacy {

// The wrapper's HLSL; `error` is set (and the result empty) when the arguments do not fit.
std::string entry_wrapper(const FunctionSignature& function, const CompileStatement& statement, const std::string& entry_name,
                          std::string& error);

}  // namespace fxview::legacy
