// The shared vertex stage every effect reuses: world-space position and tangent frame, and the
// texture coordinate, as the outputs of `StandardVS`. Later CPU comparisons capture exactly these.
#pragma once

uniform mat4 World : WORLD;
uniform mat3 WorldInverseTranspose : WORLDINVERSETRANSPOSE;
uniform mat4 ViewProjection : VIEWPROJECTION;
uniform vec3 CameraPosition : CAMERAPOSITION;
uniform vec3 LightPosition : LIGHTPOSITION;

GLSLShader StandardVS {
    layout(location = 0) in vec3 in_position;
    layout(location = 1) in vec3 in_normal;
    layout(location = 2) in vec3 in_tangent;
    layout(location = 3) in vec3 in_bitangent;
    layout(location = 4) in vec2 in_uv;

    out VertexData {
        vec3 world_position;
        vec3 normal;
        vec3 tangent;
        vec3 bitangent;
        vec2 uv;
    } vs_out;

    void main() {
        vec4 world = World * vec4(in_position, 1.0);
        vs_out.world_position = world.xyz;
        vs_out.normal = WorldInverseTranspose * in_normal;
        vs_out.tangent = mat3(World) * in_tangent;
        vs_out.bitangent = mat3(World) * in_bitangent;
        vs_out.uv = in_uv;
        gl_Position = ViewProjection * world;
    }
}
