// Compiling and linking GLSL programs, with the driver's log in the error message.
#pragma once
#include <string>
#include <vector>

#include "core/error.hpp"
#include "gl/objects.hpp"

namespace fxview::gl {

struct ShaderSource {
    GLenum stage = GL_VERTEX_SHADER;
    std::string source;
    std::string label;  // where the source came from, for messages
};

// Thrown when a stage does not compile or the program does not link; what() holds label and log.
struct ShaderError : Error {
    ShaderError(const std::string& label, const std::string& summary, std::string driver_log)
        : Error(label + ": " + summary + ":\n" + driver_log), label(label), summary(summary), log(std::move(driver_log)) {}
    std::string label;    // which shader or program
    std::string summary;  // "fragment shader does not compile", "program does not link"
    std::string log;      // the driver's info log alone
};

Program link_program(const std::vector<ShaderSource>& stages);

const char* stage_name(GLenum stage);

}  // namespace fxview::gl
