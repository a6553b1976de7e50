// GLSL the viewer's own passes share (display pass, texture inspector).
#pragma once

namespace fxview::ui {

// A full-screen triangle from gl_VertexID (no vertex buffer); uv runs 0..1 from the bottom left.
inline constexpr const char* kFullscreenVertexShader = R"(#version 450 core
out vec2 uv;
void main() {
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    uv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
})";

// IEC 61966-2-1 encoding, the same curve as image::srgb_encode (spliced into fragment shaders).
inline constexpr const char* kSrgbEncodeGlsl = R"(
vec3 encode(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
)";

}  // namespace fxview::ui
