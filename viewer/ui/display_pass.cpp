#include "ui/display_pass.hpp"

#include <string>

#include "gl/program.hpp"
#include "image/display_transform.hpp"
#include "ui/ui_shaders.hpp"

namespace fxview::ui {

namespace {

// Blends over a dark grey so that uncovered (alpha 0) pixels read as background, applies exposure and
// the tone mapper (image/display_transform.hpp), then encodes.
const std::string kFragment = std::string(R"(#version 450 core
in vec2 uv;
uniform sampler2D u_source;
uniform bool u_srgb;
uniform float u_backdrop;
uniform float u_exposure;
uniform int u_tone_map;
layout(location = 0) out vec4 color;
)") + kSrgbEncodeGlsl + image::kDisplayTransformGlsl + R"(
void main() {
    vec4 linear = texelFetch(u_source, ivec2(gl_FragCoord.xy), 0);
    vec3 shown = display_transform(mix(vec3(u_backdrop), linear.rgb, clamp(linear.a, 0.0, 1.0)), u_exposure, u_tone_map);
    color = vec4(u_srgb ? encode(shown) : shown, 1.0);
})";

}  // namespace

DisplayPass::DisplayPass()
    : program_(gl::link_program({{GL_VERTEX_SHADER, kFullscreenVertexShader, "display pass"}, {GL_FRAGMENT_SHADER, kFragment, "display pass"}})),
      vertex_array_(gl::create_vertex_array()) {}

void DisplayPass::run(GLuint source, int width, int height, bool srgb, const image::DisplaySettings& display) {
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
    glProgramUniform1f(program_.get(), glGetUniformLocation(program_.get(), "u_exposure"), display.exposure_ev);
    glProgramUniform1i(program_.get(), glGetUniformLocation(program_.get(), "u_tone_map"), static_cast<int>(display.tone_map));
    glBindVertexArray(vertex_array_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace fxview::ui
