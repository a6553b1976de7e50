// The techniques of a BRDF Explorer file (`.brdf`, viewer/effect/brdf_file.hpp): included after the
// file's shader block, which defines vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) with unit
// vectors to the light and the eye, the normal, the tangent and the bitangent (X × Y = N).
// Names here start with fx/Fx so that they do not collide with the file's own helpers.
#include "environment.glsl"
#include "area_light.glsl"

uniform float LightIrradiance < string UIName = "Light irradiance E"; float UIMin = 0; float UIMax = 20; float UIStep = 0.1; string UIGroup = "Light";
                                string UIHelp = "Irradiance the point light delivers at normal incidence (no distance fall-off); a scene light intensity (--light-intensity, Scene tab) sets it in lux"; string SceneLight = "irradiance"; > = 3.0;

// BRDF() at a surface point, and n·l; 0 where the light or the eye is below the surface.
vec3 fx_brdf_at(vec3 position, vec3 normal, vec3 tangent, out float nl) {
    vec3 n = normalize(normal);
    vec3 l = normalize(LightPosition - position);
    vec3 v = normalize(CameraPosition - position);
    // The mesh's tangent made orthogonal to n (any perpendicular where it is parallel to n).
    vec3 x = tangent - n * dot(n, tangent);
    if (dot(x, x) < 1e-12) x = cross(n, abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0));
    x = normalize(x);
    vec3 y = cross(n, x);
    nl = dot(n, l);
    return nl > 0.0 && dot(n, v) > 0.0 ? vec3(BRDF(l, v, n, x, y)) : vec3(0.0);
}

GLSLShader FxBrdfLitFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return vec3(BRDF(L, V, N, X, Y)); }
    #include "environment_light.glsl"
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        float nl;
        vec3 f = fx_brdf_at(fs_in.world_position, fs_in.normal, fs_in.tangent, nl);
        // A BRDF undefined at some directions (0/0, acos of 1 + rounding) is drawn black here, so that
        // it cannot spread through filtering; BrdfValue keeps the raw value, brdf-check counts them.
        if (any(isnan(f)) || any(isinf(f))) f = vec3(0.0);
        color = vec4(f * LightIrradiance * max(nl, 0.0), 1.0);
        // The environment's light, sampled about the mirror direction with a medium lobe (the file's
        // own lobe is unknown; the estimate is unbiased whatever it is), and a sized scene light, whose
        // lobe directions follow the width measured from the file's BRDF at this pixel.
        vec3 n = normalize(fs_in.normal), v = normalize(CameraPosition - fs_in.world_position);
        vec3 x = fs_in.tangent - n * dot(n, fs_in.tangent);
        if (dot(x, x) < 1e-12) x = cross(n, abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0));
        x = normalize(x);
        if (scene_light_sized()) color.rgb = LightIrradiance * scene_light_brdf(fs_in.world_position, n, v, x, cross(n, x), brdf_lobe_width(n, v, x, cross(n, x), 0.3));
        color.rgb += environment_light(n, v, x, cross(n, x), 0.3);
        fx_capture();
    }
}

GLSLShader FxBrdfValueFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        float nl;
        color = vec4(fx_brdf_at(fs_in.world_position, fs_in.normal, fs_in.tangent, nl), 1.0);
        fx_capture();
    }
}

technique Lit < bool Default = true; string UIName = "Lit by the point light and the environment";
                string UIHelp = "Outgoing radiance f(l, v) E (n.l) under the scene's point light (under a sized light f cos integrated over it), plus the environment's light (32 filtered samples), linear RGB"; >
    { pass p0 { VertexShader = StandardVS; FragmentShader = FxBrdfLitFS; } }
technique BrdfValue < string UIName = "BRDF value f(l, v)";
                      string UIHelp = "The BRDF itself at each fragment, without the light's irradiance or n.l"; >
    { pass p0 { VertexShader = StandardVS; FragmentShader = FxBrdfValueFS; } }

#include "brdf_grid.glsl"
