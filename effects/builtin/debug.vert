#version 450 core
// The shared vertex stage of the built-in debug views: world-space position and tangent frame,
// texture coordinate. (The effect-file library reuses the same outputs.)
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec3 in_tangent;
layout(location = 3) in vec3 in_bitangent;
layout(location = 4) in vec2 in_uv;

uniform mat4 u_world;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_projection;

out VertexData {
    vec3 world_position;
    vec3 normal;
    vec3 tangent;
    vec3 bitangent;
    vec2 uv;
} vs_out;

void main() {
    vec4 world = u_world * vec4(in_position, 1.0);
    vs_out.world_position = world.xyz;
    vs_out.normal = u_normal_matrix * in_normal;
    vs_out.tangent = mat3(u_world) * in_tangent;
    vs_out.bitangent = mat3(u_world) * in_bitangent;
    vs_out.uv = in_uv;
    gl_Position = u_view_projection * world;
}
