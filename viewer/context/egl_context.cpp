// Headless EGL: the surfaceless platform (EGL_MESA_platform_surfaceless) that Mesa and NVIDIA both
// offer, with EGL_EXT_platform_device as a fallback for drivers without it. Linked through glvnd's
// libEGL, so the vendor library (Mesa or NVIDIA) is picked at run time and one binary serves both.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>

#include "context/backends.hpp"
#include "core/error.hpp"

namespace fxview::context::detail {
namespace {

bool has_extension(const char* list, const char* name) {
    if (!list) return false;
    const size_t length = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)); p += length)
        if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
    return false;
}

std::string egl_error_text(const char* what) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", eglGetError());
    return std::string("egl: ") + what + " failed (EGL error " + code + ")";
}

EGLDisplay open_display(bool device_only) {
    const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!device_only && get_platform_display && has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
    }
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (get_platform_display && query_devices && has_extension(client_extensions, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (query_devices(8, devices, &count))
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay display = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
            }
    }
    throw Error(std::string("egl: no ") + (device_only ? "device" : "surfaceless or device") +
                " platform display could be initialised (is Mesa's libegl-mesa0 or an NVIDIA driver installed?)");
}

class EglContext final : public Context {
public:
    explicit EglContext(const ContextOptions& options) {
        display_ = open_display(options.backend == Backend::EglDevice);
        if (!eglBindAPI(EGL_OPENGL_API)) {
            eglTerminate(display_);
            throw Error(egl_error_text("eglBindAPI(EGL_OPENGL_API)"));
        }
        const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
        if (!has_extension(extensions, "EGL_KHR_surfaceless_context")) {
            eglTerminate(display_);
            throw Error("egl: the display lacks EGL_KHR_surfaceless_context");
        }
        EGLConfig config = nullptr;
        const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint config_count = 0;
        if (!eglChooseConfig(display_, config_attributes, &config, 1, &config_count) || config_count == 0) {
            if (!has_extension(extensions, "EGL_KHR_no_config_context")) {
                eglTerminate(display_);
                throw Error("egl: no OpenGL-capable config");
            }
            config = EGL_NO_CONFIG_KHR;
        }
        const EGLint context_attributes[] = {
            EGL_CONTEXT_MAJOR_VERSION, 4,
            EGL_CONTEXT_MINOR_VERSION, 5,
            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
            EGL_CONTEXT_OPENGL_DEBUG, options.debug_output ? EGL_TRUE : EGL_FALSE,
            EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attributes);
        if (context_ == EGL_NO_CONTEXT) {
            const std::string message = egl_error_text("eglCreateContext for OpenGL 4.5 core");
            eglTerminate(display_);
            throw Error(message);
        }
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            const std::string message = egl_error_text("eglMakeCurrent without a surface");
            release();
            throw Error(message);
        }
        try {
            load_gl(reinterpret_cast<GetProcAddress>(&eglGetProcAddress), "egl", options.debug_output);
        } catch (...) {
            release();
            throw;
        }
    }
    ~EglContext() override { release(); }

    Backend backend() const override { return Backend::Egl; }

private:
    void release() {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
        display_ = EGL_NO_DISPLAY;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> create_egl_context(const ContextOptions& options) {
    return std::make_unique<EglContext>(options);
}

}  // namespace fxview::context::detail
