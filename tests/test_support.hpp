// Helpers shared by the test executables: a scratch folder and one GL context per process.
#pragma once
#include <doctest/doctest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
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

// Runs the fxview binary with `arguments` (a shell command line), capturing stdout, stderr and
// the exit code; a crash (signal) fails the calling test.
struct Result {
    int exit_code = -1;
    std::string out, err;
};

inline Result run(const std::string& arguments) {
    // One file per process and call: CTest runs test binaries side by side, and a shared name lets
    // one test read another's messages.
    static int calls = 0;
    const std::string err_file = temp_path("stderr-" + std::to_string(getpid()) + "-" + std::to_string(++calls) + ".txt");
    const std::string command = std::string(FXVIEW_BINARY) + " " + arguments + " 2>" + err_file;
    Result result;
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::array<char, 4096> buffer{};
    size_t count;
    while ((count = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), count);
    const int status = pclose(pipe);
    REQUIRE(WIFEXITED(status));  // a signal (crash) fails here
    result.exit_code = WEXITSTATUS(status);
    std::ifstream err(err_file);
    std::stringstream text;
    text << err.rdbuf();
    result.err = text.str();
    err.close();
    std::filesystem::remove(err_file);
    return result;
}

}  // namespace fxview::test
