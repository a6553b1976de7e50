// OSMesa, Mesa's off-screen software path. libOSMesa exports its own gl* symbols, which would clash
// with glvnd's libOpenGL used by the EGL path; so it is never linked: it is dlopen'ed with RTLD_LOCAL
// and every GL entry point is taken from OSMesaGetProcAddress.
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <string>
#include <vector>

#include "context/backends.hpp"
#include "core/error.hpp"

namespace fxview::context::detail {
namespace {

// Rendering goes to framebuffer objects; this buffer only satisfies OSMesaMakeCurrent.
constexpr int kDefaultBufferSize = 16;

class OsMesaLibrary {
public:
    OsMesaLibrary() {
        for (const char* name : {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"}) {
            handle_ = dlopen(name, RTLD_NOW | RTLD_LOCAL);
            if (handle_) break;
        }
        if (!handle_)
            throw Error(std::string("osmesa: cannot load libOSMesa (install libosmesa6): ") + dlerror());
        create_context = symbol<decltype(&OSMesaCreateContextAttribs)>("OSMesaCreateContextAttribs");
        destroy_context = symbol<decltype(&OSMesaDestroyContext)>("OSMesaDestroyContext");
        make_current = symbol<decltype(&OSMesaMakeCurrent)>("OSMesaMakeCurrent");
        get_proc_address = symbol<decltype(&OSMesaGetProcAddress)>("OSMesaGetProcAddress");
    }
    ~OsMesaLibrary() {
        if (handle_) dlclose(handle_);
    }
    OsMesaLibrary(const OsMesaLibrary&) = delete;
    OsMesaLibrary& operator=(const OsMesaLibrary&) = delete;

    decltype(&OSMesaCreateContextAttribs) create_context = nullptr;
    decltype(&OSMesaDestroyContext) destroy_context = nullptr;
    decltype(&OSMesaMakeCurrent) make_current = nullptr;
    decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;

private:
    template <typename Function>
    Function symbol(const char* name) {
        void* address = dlsym(handle_, name);
        if (!address) {
            dlclose(handle_);
            handle_ = nullptr;
            throw Error(std::string("osmesa: libOSMesa lacks ") + name);
        }
        return reinterpret_cast<Function>(address);
    }
    void* handle_ = nullptr;
};

ProcAddress lookup(void* library, const char* name) {
    return reinterpret_cast<ProcAddress>(static_cast<const OsMesaLibrary*>(library)->get_proc_address(name));
}

class OsMesaContext final : public Context {
public:
    explicit OsMesaContext(const ContextOptions& options) : buffer_(kDefaultBufferSize * kDefaultBufferSize * 4) {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS, 24,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 4,
                                  OSMESA_CONTEXT_MINOR_VERSION, 5,
                                  0};
        context_ = library_.create_context(attributes, nullptr);
        if (!context_) throw Error("osmesa: cannot create an OpenGL 4.5 core context");
        if (!library_.make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, kDefaultBufferSize,
                                   kDefaultBufferSize)) {
            library_.destroy_context(context_);
            throw Error("osmesa: OSMesaMakeCurrent failed");
        }
        try {
            load_gl(&lookup, &library_, "osmesa", options.debug_output);
        } catch (...) {
            library_.destroy_context(context_);
            throw;
        }
    }
    ~OsMesaContext() override { library_.destroy_context(context_); }

    Backend backend() const override { return Backend::OsMesa; }

private:
    OsMesaLibrary library_;
    std::vector<unsigned char> buffer_;
    OSMesaContext context_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> create_osmesa_context(const ContextOptions& options) {
    return std::make_unique<OsMesaContext>(options);
}

}  // namespace fxview::context::detail
