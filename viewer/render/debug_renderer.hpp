// Draws a scene with one of the built-in debug views (normals, texture coordinates, vector to
// camera, vector to light; seed 002 ch. 4.1) into a render target. Meshes are uploaded once and
// kept for later frames.
#pragma once
#include <string>
#include <string_view>

#include "gl/objects.hpp"
#include "gl/render_target.hpp"
#include "render/mesh_cache.hpp"
#include "scene/scene.hpp"

namespace fxview::render {

enum class DebugView { Normals = 0, TexCoords = 1, ToCamera = 2, ToLight = 3, Plain = 4 };

DebugView parse_debug_view(std::string_view name);  // normals|uv|camera|light|plain; UsageError otherwise
std::string_view debug_view_name(DebugView view);

class DebugRenderer {
public:
    DebugRenderer();  // compiles the built-in program; needs a current context
    // `clear`: start the frame (false: draw over what the target holds, for mixed renderers).
    void render(const scene::Scene& scene, DebugView view, const gl::RenderTarget& target, bool clear = true);
    // Draws the objects into whatever framebuffer is bound, with the current states (legacy
    // effects' ScriptExternal: the scene that a post-processing effect works on).
    void draw_objects(const scene::Scene& scene, DebugView view, float aspect);

private:
    gl::Program program_;
    struct Locations {
        GLint view_projection, mode, camera_position, light_position, world, normal_matrix;
    } locations_;  // looked up once, not per draw
    MeshCache meshes_;
};

}  // namespace fxview::render
