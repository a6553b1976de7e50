// Internal to the context module: one factory per backend and the shared glad loading step.
#pragma once
#include <memory>

#include "context/context.hpp"

namespace fxview::context::detail {

using ProcAddress = void (*)();
using GetProcAddress = ProcAddress (*)(const char* name);
// A lookup that carries its backend's state (OSMesa's dlopen'ed library) instead of a global.
using GetProcAddressWithState = ProcAddress (*)(void* state, const char* name);

// Loads every GL 4.5 entry point through the lookup and checks that a 4.5 core context is current.
// Lives in its own translation unit so that backend headers (OSMesa's GL/gl.h) never meet glad's.
void load_gl(GetProcAddressWithState get_proc, void* state, const char* backend_label, bool debug_output);
void load_gl(GetProcAddress get_proc, const char* backend_label, bool debug_output);

std::unique_ptr<Context> create_egl_context(const ContextOptions& options);
std::unique_ptr<Context> create_osmesa_context(const ContextOptions& options);
std::unique_ptr<Context> create_glfw_context(const ContextOptions& options);

}  // namespace fxview::context::detail
