#include "gl/program.hpp"

namespace fxview::gl {

const char* stage_name(GLenum stage) {
    switch (stage) {
        case GL_VERTEX_SHADER: return "vertex";
        case GL_FRAGMENT_SHADER: return "fragment";
        case GL_GEOMETRY_SHADER: return "geometry";
        case GL_COMPUTE_SHADER: return "compute";
        case GL_TESS_CONTROL_SHADER: return "tessellation control";
        case GL_TESS_EVALUATION_SHADER: return "tessellation evaluation";
        default: return "unknown";
    }
}

namespace {

// The info log of a shader or program, read through the matching pair of GL queries.
std::string info_log(GLuint object, PFNGLGETSHADERIVPROC get_parameter, PFNGLGETSHADERINFOLOGPROC get_log) {
    GLint length = 0;
    get_parameter(object, GL_INFO_LOG_LENGTH, &length);
    if (length <= 0) return {};
    std::string log(static_cast<size_t>(length), '\0');
    get_log(object, length, nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

Shader compile(const ShaderSource& source) {
    Shader shader(glCreateShader(source.stage));
    const char* text = source.source.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (!ok)
        throw ShaderError(source.label, std::string(stage_name(source.stage)) + " shader does not compile",
                          info_log(shader.get(), glGetShaderiv, glGetShaderInfoLog));
    return shader;
}

}  // namespace

Program link_program(const std::vector<ShaderSource>& stages) {
    std::vector<Shader> shaders;
    shaders.reserve(stages.size());
    for (const auto& stage : stages) shaders.push_back(compile(stage));
    Program program(glCreateProgram());
    for (const auto& shader : shaders) glAttachShader(program.get(), shader.get());
    glLinkProgram(program.get());
    for (const auto& shader : shaders) glDetachShader(program.get(), shader.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string label = stages.empty() ? std::string("program") : stages.front().label;
        throw ShaderError(label, "program does not link", info_log(program.get(), glGetProgramiv, glGetProgramInfoLog));
    }
    return program;
}

}  // namespace fxview::gl
