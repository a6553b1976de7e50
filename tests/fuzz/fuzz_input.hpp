// What every harness shares: the input written to a file of a given name (the loaders read files,
// as fxview does), and the rule that a loader may only fail with fxview's own errors. Any other
// exception (std::filesystem_error, std::out_of_range, ...) escapes and libFuzzer reports it.
#pragma once
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"

namespace fxview::fuzz {

// A folder of this process's own, so that parallel fuzzing jobs never share files.
inline std::filesystem::path work_folder() {
    static const std::filesystem::path folder = [] {
        auto path = std::filesystem::temp_directory_path() / ("fxview-fuzz-" + std::to_string(getpid()));
        std::filesystem::create_directories(path);
        return path;
    }();
    return folder;
}

inline std::string write_input(const std::uint8_t* data, size_t size, const std::string& name) {
    const std::string path = (work_folder() / name).string();
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

// Runs `load`; fxview's documented errors are the expected way to reject an input.
template <typename Load>
void expect_only_fxview_errors(Load&& load) {
    try {
        load();
    } catch (const fxview::Error&) {
    } catch (const fxview::UsageError&) {
    }
}

}  // namespace fxview::fuzz
