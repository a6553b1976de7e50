// Error categories shared by every module. The CLI maps them to exit codes:
// UsageError -> 2 (the user asked for something that makes no sense), Error -> 1 (GL, I/O, data).
#pragma once
#include <stdexcept>
#include <string>

namespace fxview {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace fxview
