// A window with a GL 4.5 core context through GLFW (X11/GLX or Wayland/EGL, as GLFW decides).
#define GLFW_INCLUDE_NONE  // glad provides the GL declarations
#include <GLFW/glfw3.h>

#include <string>

#include "context/backends.hpp"
#include "core/error.hpp"

namespace fxview::context::detail {
namespace {

std::string last_glfw_error() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

class GlfwContext final : public Context {
public:
    explicit GlfwContext(const ContextOptions& options) {
        if (!glfwInit()) throw Error("glfw: cannot initialise (is a display available?): " + last_glfw_error());
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug_output ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_VISIBLE, options.window_visible ? GLFW_TRUE : GLFW_FALSE);
        window_ = glfwCreateWindow(options.window_width, options.window_height, options.window_title.c_str(),
                                   nullptr, nullptr);
        if (!window_) {
            const std::string message = "glfw: cannot open a window with OpenGL 4.5 core: " + last_glfw_error();
            glfwTerminate();
            throw Error(message);
        }
        glfwMakeContextCurrent(window_);
        try {
            load_gl(reinterpret_cast<GetProcAddress>(&glfwGetProcAddress), "glfw", options.debug_output);
        } catch (...) {
            glfwDestroyWindow(window_);
            glfwTerminate();
            throw;
        }
    }
    ~GlfwContext() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }

    Backend backend() const override { return Backend::Glfw; }
    GLFWwindow* window() const override { return window_; }
    void swap_buffers() override { glfwSwapBuffers(window_); }

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> create_glfw_context(const ContextOptions& options) {
    return std::make_unique<GlfwContext>(options);
}

}  // namespace fxview::context::detail
