// Helpers shared by the test executables: a scratch folder and one GL context per process.
#pragma once
#include <filesystem>
#include <string>

#include "context/context.hpp"

namespace fxview::test {

inline std::string temp_path(const std::string& name) {
    std::filesystem::create_directories(FXVIEW_TEST_TMP);
    return std::string(FXVIEW_TEST_TMP) + "/" + name;
}

// The backend comes from FXVIEW_TEST_BACKEND (CTest runs GL tests once per headless backend),
// EGL by default.
inline context::Backend test_backend() {
    const char* name = std::getenv("FXVIEW_TEST_BACKEND");
    return context::parse_backend(name ? name : "egl");
}

inline context::Context& shared_context() {
    static const auto context = [] {
        context::ContextOptions options;
        options.backend = test_backend();
        options.debug_output = true;
        return context::create_context(options);
    }();
    return *context;
}

}  // namespace fxview::test
