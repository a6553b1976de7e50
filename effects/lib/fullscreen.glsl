// A full-screen pass (Draw = Buffer): one triangle covering the viewport, made from gl_VertexID,
// with `uv` running 0..1 across the visible area.
#pragma once

GLSLShader FullscreenVS {
    out vec2 uv;
    void main() {
        vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);  // (0,0), (2,0), (0,2)
        uv = corner;
        gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
    }
}
