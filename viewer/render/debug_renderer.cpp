#include "render/debug_renderer.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "core/error.hpp"
#include "gl/program.hpp"

namespace fxview::builtin_shaders {
extern const std::string_view debug_vert;
extern const std::string_view debug_frag;
}  // namespace fxview::builtin_shaders

namespace fxview::render {

DebugView parse_debug_view(std::string_view name) {
    if (name == "normals") return DebugView::Normals;
    if (name == "uv") return DebugView::TexCoords;
    if (name == "camera") return DebugView::ToCamera;
    if (name == "light") return DebugView::ToLight;
    if (name == "plain") return DebugView::Plain;
    throw UsageError("unknown debug view '" + std::string(name) + "' (expected normals, uv, camera, light or plain)");
}

std::string_view debug_view_name(DebugView view) {
    switch (view) {
        case DebugView::Normals: return "normals";
        case DebugView::TexCoords: return "uv";
        case DebugView::ToCamera: return "camera";
        case DebugView::ToLight: return "light";
        case DebugView::Plain: return "plain";
    }
    return "?";
}

DebugRenderer::DebugRenderer()
    : program_(gl::link_program({{GL_VERTEX_SHADER, std::string(builtin_shaders::debug_vert), "effects/builtin/debug.vert"},
                                 {GL_FRAGMENT_SHADER, std::string(builtin_shaders::debug_frag),
                                  "effects/builtin/debug.frag"}})) {
    const GLuint p = program_.get();
    locations_ = {glGetUniformLocation(p, "u_view_projection"), glGetUniformLocation(p, "u_mode"),
                  glGetUniformLocation(p, "u_camera_position"), glGetUniformLocation(p, "u_light_position"),
                  glGetUniformLocation(p, "u_world"),          glGetUniformLocation(p, "u_normal_matrix")};
}

void DebugRenderer::render(const scene::Scene& scene, DebugView view, const gl::RenderTarget& target, bool clear) {
    target.bind_for_drawing();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // debug views show both sides: open OBJ meshes stay visible
    glDisable(GL_BLEND);
    if (clear) {
        glClearColor(scene.background.r, scene.background.g, scene.background.b, scene.background.a);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }

    draw_objects(scene, view, static_cast<float>(target.width()) / static_cast<float>(target.height()));
    target.resolve();
}

void DebugRenderer::draw_objects(const scene::Scene& scene, DebugView view, float aspect) {
    const glm::mat4 view_projection =
        math::perspective_matrix(scene.camera.fov_y_degrees, aspect, scene.camera.near_plane, scene.camera.far_plane) *
        math::view_matrix(scene.camera.pose);
    const GLuint program = program_.get();
    glUseProgram(program);
    glProgramUniformMatrix4fv(program, locations_.view_projection, 1, GL_FALSE,
                              glm::value_ptr(view_projection));
    glProgramUniform1i(program, locations_.mode, static_cast<int>(view));
    glProgramUniform3fv(program, locations_.camera_position, 1,
                        glm::value_ptr(math::camera_world_position(scene.camera.pose)));
    glProgramUniform3fv(program, locations_.light_position, 1,
                        glm::value_ptr(scene.light.world_position()));
    for (const auto& object : scene.objects) {
        const glm::mat4 world = math::world_matrix(object.pose, object.scale);
        glProgramUniformMatrix4fv(program, locations_.world, 1, GL_FALSE, glm::value_ptr(world));
        glProgramUniformMatrix3fv(program, locations_.normal_matrix, 1, GL_FALSE,
                                  glm::value_ptr(math::normal_matrix(world)));
        meshes_.get(object.mesh).draw();
    }
    glUseProgram(0);
}

}  // namespace fxview::render
