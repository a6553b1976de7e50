// The value of a legacy effect's default or annotation, as the DirectX and Cg compilers fold it: a
// list of numbers from literals, true/false, `{ ... }` and constructors such as float3( ... ), and
// arithmetic on them (+ - * / and parentheses: `1.0 / 2.2`, `-0.5 * 3`). Anything else (a function
// call, a name) is no constant here.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "effect/lexer.hpp"

namespace fxview::legacy {

// A number literal with HLSL/Cg suffixes (1.0f, 2h, 3u); nullopt if it is none.
std::optional<double> legacy_number(const std::string& text);

// The numbers of `tokens` (one value, without its stop), or nullopt where it is no constant.
std::optional<std::vector<double>> constant_numbers(const std::vector<effect::Token>& tokens);

}  // namespace fxview::legacy
