// Resource budgets: how much a file may make fxview read, decode or allocate. Files come from
// strangers (effects travel like documents), so every size a file claims is checked against these
// before anything is allocated. Defaults are documented in docs/effect-format.md ("Budgets");
// `--limit NAME=VALUE` changes one.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace fxview {

// A file asked for more than a budget allows (a kind of Error: exit 1, `file:line` message).
struct BudgetError : Error {
    using Error::Error;
};

struct ResourceLimits {
    std::int64_t array_elements = 65536;            // elements of one uniform array
    std::int64_t texture_dimension = 16384;         // pixels along any side (and slices of a volume)
    std::int64_t texture_bytes = 128ll << 20;       // one texture, decoded (all faces and levels)
    std::int64_t effect_texture_bytes = 192ll << 20;  // all textures of one effect, as stored
    std::int64_t data_file_bytes = 128ll << 20;     // one data file: spectra, BRDF grids, MERL, OBJ, FTXT, presets
    std::int64_t source_bytes = 512ll << 10;        // an effect with its includes expanded
    std::int64_t compile_bytes = 2ll << 20;         // GLSL handed to the driver, summed over every pass
    std::int64_t include_depth = 32;                // nested #include levels
};

// The longest environment source (a name, or six face paths of PATH_MAX): longer text is refused
// before anything splits or stats it.
inline constexpr size_t kMaxEnvironmentSourceChars = 6 * 4096 + 5;

// One budget, as the user names it: "texture-bytes", "include-depth", ...
struct LimitInfo {
    const char* name;
    std::int64_t ResourceLimits::*field;
    const char* what;
};
const std::vector<LimitInfo>& limit_infos();

// Applies "NAME=VALUE" (VALUE an integer, optionally with a K, M or G suffix for bytes);
// throws UsageError naming the known budgets.
void set_limit(ResourceLimits& limits, const std::string& assignment);

// Throws BudgetError "`where`: WHAT SIZE exceeds the budget NAME = LIMIT (--limit NAME=...)" when
// `value` is above the limit named `name`.
void check_limit(const ResourceLimits& limits, const char* name, std::int64_t value, const std::string& where,
                 const std::string& what);

// Why `path` cannot be read as a file: "no such file", or "not a regular file (a device, a pipe or
// a folder)" for /dev/zero and the like, which exist but are no files.
std::string not_a_file(const std::string& path);

// The size of a file, checked against data-file-bytes before it is read.
std::int64_t checked_file_size(const std::string& path, const ResourceLimits& limits);

}  // namespace fxview
