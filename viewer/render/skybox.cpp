#include "render/skybox.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "gl/program.hpp"
#include "math/transform.hpp"

namespace fxview::render {

namespace {

constexpr const char* kVertex = R"(#version 450 core
uniform mat4 u_inverse_rotation_projection;  // clip space -> world direction, camera translation left out
out vec3 direction;
void main() {
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    vec4 far_point = u_inverse_rotation_projection * vec4(corner, 1.0, 1.0);
    direction = far_point.xyz / far_point.w;
    gl_Position = vec4(corner, 1.0, 1.0);  // at the far plane: objects stay in front
})";

constexpr const char* kFragment = R"(#version 450 core
in vec3 direction;
uniform samplerCube u_cube;
uniform mat3 u_world_to_cube;
uniform float u_intensity;
uniform bool u_base_level;
layout(location = 0) out vec4 color;
void main() {
    vec3 d = u_world_to_cube * normalize(direction);
    color = vec4((u_base_level ? textureLod(u_cube, d, 0.0) : texture(u_cube, d)).rgb * u_intensity, 1.0);
})";

}  // namespace

Skybox::Skybox()
    : program_(gl::link_program({{GL_VERTEX_SHADER, kVertex, "skybox"}, {GL_FRAGMENT_SHADER, kFragment, "skybox"}})),
      vertex_array_(gl::create_vertex_array()),
      sampler_(gl::create_sampler()) {
    glSamplerParameteri(sampler_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glSamplerParameteri(sampler_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

void Skybox::draw(GLuint cube, const scene::Camera& camera, const gl::RenderTarget& target, const SkyboxLook& look) {
    target.bind_for_drawing();
    const float aspect = static_cast<float>(target.width()) / static_cast<float>(target.height());
    const glm::mat4 projection = math::perspective_matrix(camera.fov_y_degrees, aspect, camera.near_plane, camera.far_plane);
    const glm::mat4 rotation = math::rotation_matrix(camera.pose.rotation);
    const glm::mat4 inverse = glm::inverse(projection * rotation);
    glUseProgram(program_.get());
    glProgramUniformMatrix4fv(program_.get(), glGetUniformLocation(program_.get(), "u_inverse_rotation_projection"), 1, GL_FALSE,
                              glm::value_ptr(inverse));
    glProgramUniform1i(program_.get(), glGetUniformLocation(program_.get(), "u_cube"), 0);
    glProgramUniformMatrix3fv(program_.get(), glGetUniformLocation(program_.get(), "u_world_to_cube"), 1, GL_FALSE, glm::value_ptr(look.world_to_cube));
    glProgramUniform1f(program_.get(), glGetUniformLocation(program_.get(), "u_intensity"), look.intensity);
    glProgramUniform1i(program_.get(), glGetUniformLocation(program_.get(), "u_base_level"), look.base_level ? 1 : 0);
    glBindTextureUnit(0, cube);
    glBindSampler(0, sampler_.get());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glBindVertexArray(vertex_array_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(0, 0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glUseProgram(0);
}

}  // namespace fxview::render
