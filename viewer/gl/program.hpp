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

// Thrown when a stage does not compile or the program does not link; what() holds the log.
struct ShaderError : Error {
    using Error::Error;
};

Program link_program(const std::vector<ShaderSource>& stages);

const char* stage_name(GLenum stage);

}  // namespace fxview::gl
