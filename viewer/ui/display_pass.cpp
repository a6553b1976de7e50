#include "ui/display_pass.hpp"

#include "gl/program.hpp"

namespace fxview::ui {

namespace {

constexpr const char* kVertex = R"(#version 450 core
out vec2 uv;
void main() {
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    uv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
})";

// IEC 61966-2-1 encoding, the same curve as image::srgb_encode.
constexpr const char* kFragment = R"(#version 450 core
in vec2 uv;
uniform sampler2D u_source;
uniform bool u_srgb;
uniform float u_backdrop;
layout(location = 0) out vec4 color;
vec3 encode(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
void main() {
    vec4 linear = texelFetch(u_source, ivec2(gl_FragCoord.xy), 0);
    // Blend over a dark grey so that uncovered (alpha 0) pixels read as background.
    vec3 shown = mix(vec3(u_backdrop), linear.rgb, clamp(linear.a, 0.0, 1.0));
    color = vec4(u_srgb ? encode(shown) : clamp(shown, 0.0, 1.0), 1.0);
})";

}  // namespace

DisplayPass::DisplayPass()
    : program_(gl::link_program({{GL_VERTEX_SHADER, kVertex, "display pass"}, {GL_FRAGMENT_SHADER, kFragment, "display pass"}})),
      vertex_array_(gl::create_vertex_array()) {}

void DisplayPass::run(GLuint source, int width, int height, bool srgb) {
    if (width != width_ || height != height_) {
        texture_ = gl::create_texture(GL_TEXTURE_2D);
        glTextureStorage2D(texture_.get(), 1, GL_RGBA8, width, height);
        glTextureParameteri(texture_.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // the magnifier shows texels
        glTextureParameteri(texture_.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        framebuffer_ = gl::create_framebuffer();
        glNamedFramebufferTexture(framebuffer_.get(), GL_COLOR_ATTACHMENT0, texture_.get(), 0);
        width_ = width;
        height_ = height;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glUseProgram(program_.get());
    glBindTextureUnit(0, source);
    glProgramUniform1i(program_.get(), glGetUniformLocation(program_.get(), "u_source"), 0);
    glProgramUniform1i(program_.get(), glGetUniformLocation(program_.get(), "u_srgb"), srgb ? 1 : 0);
    glProgramUniform1f(program_.get(), glGetUniformLocation(program_.get(), "u_backdrop"), kDisplayBackdrop);
    glBindVertexArray(vertex_array_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace fxview::ui
