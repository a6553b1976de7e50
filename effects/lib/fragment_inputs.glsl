// The fragment-side view of StandardVS's outputs; include it inside a fragment shader block.
in VertexData {
    vec3 world_position;
    vec3 normal;
    vec3 tangent;
    vec3 bitangent;
    vec2 uv;
} fs_in;
