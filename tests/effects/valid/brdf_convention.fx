// The BRDF convention for effect files: an .fx effect that defines BRDF(L, V, N, X, Y) and includes
// brdf_grid.glsl after it gets brdf-check, brdf-plot and the viewer's BRDF tab. Here: Lambert plus a
// normalised Blinn-Phong lobe, drawn by a technique of its own.
#include "standard.glsl"

uniform vec3 Diffuse < string UIName = "Diffuse reflectance"; string UIWidget = "color"; > = {0.5, 0.4, 0.3};
uniform float Exponent < string UIName = "Exponent"; float UIMin = 1; float UIMax = 1000; > = 60.0;
uniform float Specular < string UIName = "Specular"; float UIMin = 0; float UIMax = 1; > = 0.3;

vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {
    vec3 H = normalize(L + V);
    return Diffuse / 3.14159265 + vec3(Specular * (Exponent + 8.0) / (8.0 * 3.14159265) * pow(max(dot(N, H), 0.0), Exponent));
}

GLSLShader LitFS {
    #include "fragment_inputs.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        vec3 n = normalize(fs_in.normal), l = normalize(LightPosition - fs_in.world_position), v = normalize(CameraPosition - fs_in.world_position);
        vec3 x = normalize(cross(abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0), n));
        color = vec4(dot(n, l) > 0.0 && dot(n, v) > 0.0 ? BRDF(l, v, n, x, cross(n, x)) * 3.0 * dot(n, l) : vec3(0.0), 1.0);
    }
}

technique Lit < bool Default = true; > { pass p0 { VertexShader = StandardVS; FragmentShader = LitFS; } }

#include "brdf_grid.glsl"
