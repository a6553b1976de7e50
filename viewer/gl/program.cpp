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

std::string shader_log(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

std::string program_log(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
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
        throw ShaderError(source.label + ": " + stage_name(source.stage) + " shader does not compile:\n" +
                          shader_log(shader.get()));
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
        throw ShaderError(label + ": program does not link:\n" + program_log(program.get()));
    }
    return program;
}

}  // namespace fxview::gl
