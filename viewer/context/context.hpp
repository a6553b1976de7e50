// A current OpenGL 4.5 core context from one of three backends, chosen at run time.
// Creating a context makes it current and fills the glad loader through that backend's
// get-proc-address, so every later GL call goes to the right driver.
#pragma once
#include <memory>
#include <string>
#include <string_view>

struct GLFWwindow;

namespace fxview::context {

// Egl: surfaceless platform, falling back to the device platform; EglDevice: the device platform
// only (EGL_EXT_platform_device, what some NVIDIA drivers offer), to exercise that path anywhere.
enum class Backend { Egl, EglDevice, OsMesa, Glfw };

Backend parse_backend(std::string_view name);  // throws UsageError on an unknown name
std::string_view backend_name(Backend backend);

struct ContextOptions {
    Backend backend = Backend::Egl;
    int window_width = 640;  // only the glfw backend opens a window
    int window_height = 480;
    bool window_visible = true;
    std::string window_title = "fxview";
    bool debug_output = false;  // KHR_debug callback; on by default in debug builds
};

class Context {
public:
    virtual ~Context() = default;
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    virtual Backend backend() const = 0;
    // The window of the glfw backend; nullptr for the headless backends.
    virtual GLFWwindow* window() const { return nullptr; }
    virtual void swap_buffers() {}

protected:
    Context() = default;
};

// Throws fxview::Error with the backend's own reason when no 4.5 core context can be made.
std::unique_ptr<Context> create_context(const ContextOptions& options);

struct ContextInfo {
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string glsl_version;
    int major = 0;
    int minor = 0;
    bool core_profile = false;
};

ContextInfo query_context_info();  // of the current context

}  // namespace fxview::context
