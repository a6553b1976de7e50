#include "context/context.hpp"

#include <glad/gl.h>

#include <cstdio>

#include "context/backends.hpp"
#include "core/error.hpp"

namespace fxview::context {

Backend parse_backend(std::string_view name) {
    if (name == "egl") return Backend::Egl;
    if (name == "egl-device") return Backend::EglDevice;
    if (name == "osmesa") return Backend::OsMesa;
    if (name == "glfw") return Backend::Glfw;
    throw UsageError("unknown backend '" + std::string(name) + "' (expected egl, egl-device, osmesa or glfw)");
}

std::string_view backend_name(Backend backend) {
    switch (backend) {
        case Backend::Egl: return "egl";
        case Backend::EglDevice: return "egl-device";
        case Backend::OsMesa: return "osmesa";
        case Backend::Glfw: return "glfw";
    }
    return "?";
}

std::unique_ptr<Context> create_context(const ContextOptions& options) {
    switch (options.backend) {
        case Backend::Egl:
        case Backend::EglDevice: return detail::create_egl_context(options);
        case Backend::OsMesa: return detail::create_osmesa_context(options);
        case Backend::Glfw: return detail::create_glfw_context(options);
    }
    throw UsageError("unknown backend");
}

static std::string gl_string(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? text : "";
}

ContextInfo query_context_info() {
    ContextInfo info;
    info.vendor = gl_string(GL_VENDOR);
    info.renderer = gl_string(GL_RENDERER);
    info.version = gl_string(GL_VERSION);
    info.glsl_version = gl_string(GL_SHADING_LANGUAGE_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &info.major);
    glGetIntegerv(GL_MINOR_VERSION, &info.minor);
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    info.core_profile = (profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
    return info;
}

namespace detail {

static void GLAD_API_PTR print_debug_message(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei,
                                             const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;  // driver chatter, not problems
    std::fprintf(stderr, "GL debug [%s, id %u]: %s\n",
                 type == GL_DEBUG_TYPE_ERROR ? "error" : "warning", id, message);
}

void load_gl(GetProcAddress get_proc, const char* backend_label, bool debug_output) {
    const auto forward = [](void* state, const char* name) {
        return reinterpret_cast<GetProcAddress>(state)(name);
    };
    load_gl(forward, reinterpret_cast<void*>(get_proc), backend_label, debug_output);
}

void load_gl(GetProcAddressWithState get_proc, void* state, const char* backend_label, bool debug_output) {
    // GLADapiproc is void (*)(void) like ProcAddress; the cast only names glad's typedef.
    const int version = gladLoadGLUserPtr(reinterpret_cast<GLADuserptrloadfunc>(get_proc), state);
    if (version == 0)
        throw Error(std::string(backend_label) + ": could not load OpenGL entry points");
    if (GLAD_VERSION_MAJOR(version) < 4 || (GLAD_VERSION_MAJOR(version) == 4 && GLAD_VERSION_MINOR(version) < 5))
        throw Error(std::string(backend_label) + ": OpenGL 4.5 core needed, the driver gives " +
                    std::to_string(GLAD_VERSION_MAJOR(version)) + "." + std::to_string(GLAD_VERSION_MINOR(version)));
    // Cube maps filter across face edges everywhere (GL's default is off): the viewer, the CLI and the
    // CPU reference then all agree, and no seams show in reflections and skyboxes.
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    if (debug_output && glDebugMessageCallback) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(print_debug_message, nullptr);
    }
}

}  // namespace detail
}  // namespace fxview::context
