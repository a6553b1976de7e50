#version 450 core
// The four debug views of the original ShaderViewer, each vector mapped to colour by eq. 55:
// n_mapped = normalize(n) * 0.5 + 0.5.
in VertexData {
    vec3 world_position;
    vec3 normal;
    vec3 tangent;
    vec3 bitangent;
    vec2 uv;
} fs_in;

uniform int u_mode;  // 0 normals, 1 texture coordinates, 2 vector to camera, 3 vector to light, 4 plain Lambert
uniform vec3 u_camera_position;
uniform vec3 u_light_position;

layout(location = 0) out vec4 out_color;

vec3 map_vector(vec3 v) { return normalize(v) * 0.5 + 0.5; }

void main() {
    vec3 color;
    if (u_mode == 1)
        color = vec3(fs_in.uv, 0.0);
    else if (u_mode == 2)
        color = map_vector(u_camera_position - fs_in.world_position);
    else if (u_mode == 3)
        color = map_vector(u_light_position - fs_in.world_position);
    else if (u_mode == 4)  // plain rendering without any effect: grey Lambert, linear RGB
        color = vec3(0.8) * (0.05 + 0.95 * max(dot(normalize(fs_in.normal), normalize(u_light_position - fs_in.world_position)), 0.0));
    else
        color = map_vector(fs_in.normal);
    out_color = vec4(color, 1.0);
}
