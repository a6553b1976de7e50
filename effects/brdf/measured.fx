// A measured BRDF on any mesh, beside the Ashikhmin-Shirley model fitted to it (seed 000; BRDF
// Explorer's side-by-side view): `Measured` looks the data up by angle in a 3D texture (trilinear
// over φo, θo, θi; the file is a grid CSV or a MERL .binary, `--set Measured=FILE`), `Fitted` is eq.
// 4.28 with FitDiffuse/FitSpecular/FitExponent (which its plugin FitAshikhminShirley fills), `Difference` their
// absolute difference. Radiance L = f · E · (n·l). CPU references: viewer/reference/measured_reference.cpp.
#include "standard.glsl"
#include "brdf.glsl"
#include "area_light.glsl"

uniform sampler3D Measured < string ResourceName = "sample-brdf.csv"; string Filter = "linear"; string Wrap = "clamp";
                             string UIName = "Measured BRDF";
                             string UIHelp = "Grid CSV (theta_in_deg,theta_out_deg,phi_out_deg,r,g,b; uniform over 0..90 / 0..180) or MERL .binary"; >;
uniform float LightIrradiance < string UIName = "Light irradiance E"; float UIMin = 0; float UIMax = 20; float UIStep = 0.1; string UIGroup = "Light"; string SceneLight = "irradiance"; > = 3.0;
uniform vec3 FitDiffuse < string UIName = "cd"; string UIWidget = "color"; string UIGroup = "Ashikhmin-Shirley, simplified (fit model)"; > = {0.15, 0.10, 0.05};
uniform vec3 FitSpecular < string UIName = "cs"; string UIWidget = "color"; string UIGroup = "Ashikhmin-Shirley, simplified (fit model)"; > = {0.57, 0.39, 0.20};
uniform float FitExponent < string UIName = "ns"; float UIMin = 1; float UIMax = 10000; string UIGroup = "Ashikhmin-Shirley, simplified (fit model)"; > = 150.0;
uniform float DifferenceScale < string UIName = "Difference scale"; float UIMin = 1; float UIMax = 100; string UIGroup = "View"; > = 1.0;

// The fit as a plugin of this effect (docs/plugins.md): the viewer's Plugins tab and
// `fxview plugin run effects/brdf/measured.fx FitAshikhminShirley` fit the model to the data behind
// the Measured sampler and write cd, cs and ns into the three parameters above.
plugin FitAshikhminShirley < string Type = "brdf-fit"; string UIName = "Fit Ashikhmin-Shirley to the measured BRDF";
                             string Data = "Measured"; string Model = "ashikhmin-fit";
                             string Targets = "FitDiffuse, FitSpecular, FitExponent"; string Technique = "Fitted";
                             float Limit = 75; string Solver = "global"; >;

// The grid's angles of this fragment's light and view directions: θi, θo from the normal and φo as
// 180° minus the azimuth between them (φo = 0: the camera on the far side of the light, the mirror side).
vec3 grid_angles(Frame f) {
    vec3 lp = f.l - f.n * f.nl, vp = f.v - f.n * f.nv;
    float phi = dot(lp, lp) > 1e-12 && dot(vp, vp) > 1e-12 ? kPi - acos(clamp(dot(normalize(lp), normalize(vp)), -1.0, 1.0)) : 0.0;
    return vec3(phi, acos(clamp(f.nv, -1.0, 1.0)), acos(clamp(f.nl, -1.0, 1.0)));
}

vec3 measured(Frame f) {
    vec3 size = vec3(textureSize(Measured, 0));
    vec3 unit = grid_angles(f) / vec3(kPi, 0.5 * kPi, 0.5 * kPi);  // 0..1 over the grid
    return texture(Measured, (unit * (size - 1.0) + 0.5) / size).rgb;
}

vec3 fitted(Frame f) { return ashikhmin_shirley_fit(f, FitDiffuse, FitSpecular, FitExponent); }

Frame frame_here(vec3 position, vec3 normal, vec3 tangent) { return make_frame(position, normal, tangent, LightPosition, CameraPosition); }
vec4 radiance(Frame f, vec3 brdf) { return vec4(visible(f) ? brdf * LightIrradiance * f.nl : vec3(0.0), 1.0); }
// A sized light: E times f cos θ integrated over it (area_light_brdf.glsl), its lobe directions drawn
// about the fitted exponent's lobe.
float lobe_alpha() { return sqrt(2.0 / (FitExponent + 2.0)); }

GLSLShader MeasuredFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return measured(g); }
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        if (scene_light_sized()) color = vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), lobe_alpha()), 1.0);
        else color = radiance(f, visible(f) ? measured(f) : vec3(0.0));
        fx_capture();
    }
}

GLSLShader FittedFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return fitted(g); }
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        if (scene_light_sized()) color = vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), lobe_alpha()), 1.0);
        else color = radiance(f, visible(f) ? fitted(f) : vec3(0.0));
        fx_capture();
    }
}

GLSLShader DifferenceFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return DifferenceScale * abs(measured(g) - fitted(g)); }
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        if (scene_light_sized()) color = vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), lobe_alpha()), 1.0);
        else color = radiance(f, visible(f) ? DifferenceScale * abs(measured(f) - fitted(f)) : vec3(0.0));
        fx_capture();
    }
}

technique Measured { pass p0 { VertexShader = StandardVS; FragmentShader = MeasuredFS; } }
technique Fitted { pass p0 { VertexShader = StandardVS; FragmentShader = FittedFS; } }
technique Difference { pass p0 { VertexShader = StandardVS; FragmentShader = DifferenceFS; } }
