// Analytic BRDFs under one point light (DOMAIN.md §7): the PBR sandbox of seed 004 (metallic-
// roughness Cook-Torrance with GGX), the energy-conserving Phong and Cook-Torrance with Beckmann of
// seed 001, Ashikhmin-Shirley of seed 000 (anisotropic, and the simplified model its fitter uses),
// and the further models `fxview fit --model` offers (Cook-Torrance GGX and Beckmann with Schlick F0,
// Blinn-Phong, Ward). Outgoing radiance L = f(l, v) · E · (n·l), linear RGB. CPU references:
// viewer/reference/brdf_reference.cpp on viewer/brdf/models.cpp.
#include "standard.glsl"
#include "brdf.glsl"
#include "environment_pbr.glsl"
#include "area_light.glsl"

uniform float LightIrradiance < string UIName = "Light irradiance E"; float UIMin = 0; float UIMax = 20; float UIStep = 0.1; string UIGroup = "Light";
                                string UIHelp = "Irradiance the point light delivers at normal incidence (no distance fall-off); a scene light intensity (--light-intensity, Scene tab) sets it in lux"; string SceneLight = "irradiance"; > = 3.0;

uniform vec3 BaseColor < string UIName = "Base colour"; string UIWidget = "color"; string UIGroup = "PBR";
                         string UIHelp = "Linear F0 of metals (gold 1.00/0.71/0.29, copper 0.95/0.64/0.54), albedo of non-metals; also Lambert's albedo"; > = {1.0, 0.71, 0.29};
uniform float Metallic < string UIName = "Metallic"; float UIMin = 0; float UIMax = 1; string UIGroup = "PBR"; > = 1.0;
uniform float Roughness < string UIName = "Roughness"; float UIMin = 0.05; float UIMax = 1; string UIGroup = "PBR";
                          string UIHelp = "GGX alpha = roughness squared; Smith-Schlick k = (roughness + 1)^2 / 8"; > = 0.4;

uniform vec3 PhongDiffuse < string UIName = "kd"; string UIWidget = "color"; string UIGroup = "Modified Phong"; > = {0.5, 0.12, 0.1};
uniform float PhongSpecular < string UIName = "ks"; float UIMin = 0; float UIMax = 1; string UIGroup = "Modified Phong";
                              string UIHelp = "Energy conserving while kd + ks <= 1"; > = 0.4;
uniform float PhongExponent < string UIName = "Exponent n"; float UIMin = 1; float UIMax = 1000; string UIGroup = "Modified Phong"; > = 40.0;

uniform vec3 CTDiffuse < string UIName = "kd"; string UIWidget = "color"; string UIGroup = "Cook-Torrance (Beckmann)"; > = {0.1, 0.2, 0.5};
uniform float CTSpecular < string UIName = "ks"; float UIMin = 0; float UIMax = 1; string UIGroup = "Cook-Torrance (Beckmann)"; > = 1.0;
uniform float BeckmannM < string UIName = "Slope m"; float UIMin = 0.02; float UIMax = 1; string UIGroup = "Cook-Torrance (Beckmann)";
                          string UIHelp = "RMS slope of the microfacets"; > = 0.3;
uniform float Eta < string UIName = "Index of refraction"; float UIMin = 1; float UIMax = 3; float UIStep = 0.01; string UIGroup = "Cook-Torrance (Beckmann)"; > = 1.5;
uniform bool PrintedBeckmann < string UIName = "Beckmann as printed"; string UIGroup = "Cook-Torrance (Beckmann)";
                               string UIHelp = "A common misprint: 1/(4 m^2 cos^4) instead of the normalised 1/(pi m^2 cos^4); highlights 4/pi too bright"; > = false;

uniform vec3 ASDiffuse < string UIName = "Rd"; string UIWidget = "color"; string UIGroup = "Ashikhmin-Shirley"; > = {0.45, 0.3, 0.15};
uniform vec3 ASSpecular < string UIName = "Rs"; string UIWidget = "color"; string UIGroup = "Ashikhmin-Shirley"; > = {0.3, 0.3, 0.3};
uniform float Nu < string UIName = "nu (along the tangent)"; float UIMin = 1; float UIMax = 10000; string UIGroup = "Ashikhmin-Shirley"; > = 20.0;
uniform float Nv < string UIName = "nv (across)"; float UIMin = 1; float UIMax = 10000; string UIGroup = "Ashikhmin-Shirley"; > = 500.0;

uniform vec3 FitDiffuse < string UIName = "cd"; string UIWidget = "color"; string UIGroup = "Ashikhmin-Shirley, simplified (fit model)"; > = {0.2, 0.2, 0.2};
uniform vec3 FitSpecular < string UIName = "cs"; string UIWidget = "color"; string UIGroup = "Ashikhmin-Shirley, simplified (fit model)"; > = {0.2, 0.2, 0.2};
uniform float FitExponent < string UIName = "ns"; float UIMin = 1; float UIMax = 10000; string UIGroup = "Ashikhmin-Shirley, simplified (fit model)"; > = 50.0;

uniform vec3 GGXDiffuse < string UIName = "kd"; string UIWidget = "color"; string UIGroup = "Cook-Torrance (GGX)"; > = {0.05, 0.05, 0.05};
uniform vec3 GGXF0 < string UIName = "F0 (reflectance at normal incidence)"; string UIWidget = "color"; string UIGroup = "Cook-Torrance (GGX)"; > = {0.9, 0.6, 0.3};
uniform float GGXAlpha < string UIName = "Width alpha"; float UIMin = 0.001; float UIMax = 1; float UIStep = 0.001; string UIGroup = "Cook-Torrance (GGX)";
                         string UIHelp = "GGX width (alpha itself, not roughness squared); height-correlated Smith shadowing"; > = 0.2;

uniform vec3 CTSDiffuse < string UIName = "kd"; string UIWidget = "color"; string UIGroup = "Cook-Torrance (Beckmann, Schlick F0)"; > = {0.3, 0.1, 0.05};
uniform vec3 CTSF0 < string UIName = "F0 (reflectance at normal incidence)"; string UIWidget = "color"; string UIGroup = "Cook-Torrance (Beckmann, Schlick F0)"; > = {0.04, 0.04, 0.04};
uniform float CTSSlope < string UIName = "Slope m"; float UIMin = 0.001; float UIMax = 1; float UIStep = 0.001; string UIGroup = "Cook-Torrance (Beckmann, Schlick F0)";
                         string UIHelp = "RMS slope of the microfacets; V-cavity shadowing"; > = 0.2;

uniform vec3 BlinnDiffuse < string UIName = "kd"; string UIWidget = "color"; string UIGroup = "Blinn-Phong"; > = {0.4, 0.1, 0.1};
uniform vec3 BlinnSpecular < string UIName = "ks"; string UIWidget = "color"; string UIGroup = "Blinn-Phong"; > = {0.3, 0.3, 0.3};
uniform float BlinnExponent < string UIName = "Exponent n"; float UIMin = 0.01; float UIMax = 10000; string UIGroup = "Blinn-Phong";
                              string UIHelp = "Normalised lobe (n + 8)/(8 pi) (n.h)^n"; > = 50.0;

uniform vec3 WardDiffuse < string UIName = "kd"; string UIWidget = "color"; string UIGroup = "Ward"; > = {0.1, 0.3, 0.1};
uniform vec3 WardSpecular < string UIName = "ks"; string UIWidget = "color"; string UIGroup = "Ward"; > = {0.1, 0.1, 0.1};
uniform float WardAlpha < string UIName = "Width alpha"; float UIMin = 0.001; float UIMax = 1; float UIStep = 0.001; string UIGroup = "Ward";
                          string UIHelp = "RMS slope of the isotropic Ward lobe"; > = 0.15;

// Every technique: f at this fragment times E (n·l) under a point light, black where light or eye is
// below the surface; under a sized light E times f cos θ integrated over it (area_light_brdf.glsl,
// sampled about a GGX lobe of the model's rough width).
Frame frame_here(vec3 position, vec3 normal, vec3 tangent) { return make_frame(position, normal, tangent, LightPosition, CameraPosition); }
vec4 radiance(Frame f, vec3 brdf) { return vec4(visible(f) ? brdf * LightIrradiance * f.nl : vec3(0.0), 1.0); }

GLSLShader LambertFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return BaseColor / kPi; }
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), 1.0), 1.0)
                                    : radiance(f, visible(f) ? BaseColor / kPi : vec3(0.0));
        color.rgb += BaseColor * environment_irradiance(environment_facing_normal(f.n, f.v));
        fx_capture();
    }
}

GLSLShader PBRFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return metallic_roughness(frame_of(L, V, N, X), BaseColor, Metallic, Roughness); }
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), Roughness * Roughness), 1.0)
                                    : radiance(f, visible(f) ? metallic_roughness(f, BaseColor, Metallic, Roughness) : vec3(0.0));
        color.rgb += metallic_roughness_environment(f, BaseColor, Metallic, Roughness);
        fx_capture();
    }
}

GLSLShader ModifiedPhongFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return modified_phong(g, PhongDiffuse, PhongSpecular, PhongExponent); }
    #include "environment_light.glsl"
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        float alpha = clamp(sqrt(2.0 / (4.0 * PhongExponent + 2.0)), 0.001, 1.0);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), alpha), 1.0)
                                    : radiance(f, visible(f) ? modified_phong(f, PhongDiffuse, PhongSpecular, PhongExponent) : vec3(0.0));
        color.rgb += environment_light(f.n, f.v, f.t, cross(f.n, f.t), alpha);
        fx_capture();
    }
}

GLSLShader CookTorranceBeckmannFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return cook_torrance_beckmann(g, CTDiffuse, CTSpecular, BeckmannM, Eta, PrintedBeckmann); }
    #include "environment_light.glsl"
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        float alpha = clamp(BeckmannM, 0.001, 1.0);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), alpha), 1.0)
                                    : radiance(f, visible(f) ? cook_torrance_beckmann(f, CTDiffuse, CTSpecular, BeckmannM, Eta, PrintedBeckmann) : vec3(0.0));
        color.rgb += environment_light(f.n, f.v, f.t, cross(f.n, f.t), alpha);
        fx_capture();
    }
}

GLSLShader AshikhminShirleyFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return ashikhmin_shirley(g, ASDiffuse, ASSpecular, Nu, Nv); }
    #include "environment_light.glsl"
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        float alpha = clamp(sqrt(2.0 / (sqrt(Nu * Nv) + 2.0)), 0.001, 1.0);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), alpha), 1.0)
                                    : radiance(f, visible(f) ? ashikhmin_shirley(f, ASDiffuse, ASSpecular, Nu, Nv) : vec3(0.0));
        color.rgb += environment_light(f.n, f.v, f.t, cross(f.n, f.t), alpha);
        fx_capture();
    }
}

GLSLShader AshikhminShirleyFitFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return ashikhmin_shirley_fit(g, FitDiffuse, FitSpecular, FitExponent); }
    #include "environment_light.glsl"
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        float alpha = clamp(sqrt(2.0 / (FitExponent + 2.0)), 0.001, 1.0);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), alpha), 1.0)
                                    : radiance(f, visible(f) ? ashikhmin_shirley_fit(f, FitDiffuse, FitSpecular, FitExponent) : vec3(0.0));
        color.rgb += environment_light(f.n, f.v, f.t, cross(f.n, f.t), alpha);
        fx_capture();
    }
}

GLSLShader CookTorranceGGXFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return cook_torrance_ggx(g, GGXDiffuse, GGXF0, GGXAlpha); }
    #include "environment_light.glsl"
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        float alpha = clamp(GGXAlpha, 0.001, 1.0);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), alpha), 1.0)
                                    : radiance(f, visible(f) ? cook_torrance_ggx(f, GGXDiffuse, GGXF0, GGXAlpha) : vec3(0.0));
        color.rgb += environment_light(f.n, f.v, f.t, cross(f.n, f.t), alpha);
        fx_capture();
    }
}

GLSLShader CookTorranceBeckmannSchlickFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return cook_torrance_beckmann_schlick(g, CTSDiffuse, CTSF0, CTSSlope); }
    #include "environment_light.glsl"
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        float alpha = clamp(CTSSlope, 0.001, 1.0);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), alpha), 1.0)
                                    : radiance(f, visible(f) ? cook_torrance_beckmann_schlick(f, CTSDiffuse, CTSF0, CTSSlope) : vec3(0.0));
        color.rgb += environment_light(f.n, f.v, f.t, cross(f.n, f.t), alpha);
        fx_capture();
    }
}

GLSLShader BlinnPhongFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return blinn_phong(g, BlinnDiffuse, BlinnSpecular, BlinnExponent); }
    #include "environment_light.glsl"
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        float alpha = clamp(sqrt(2.0 / (BlinnExponent + 2.0)), 0.001, 1.0);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), alpha), 1.0)
                                    : radiance(f, visible(f) ? blinn_phong(f, BlinnDiffuse, BlinnSpecular, BlinnExponent) : vec3(0.0));
        color.rgb += environment_light(f.n, f.v, f.t, cross(f.n, f.t), alpha);
        fx_capture();
    }
}

GLSLShader WardFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { Frame g = frame_of(L, V, N, X); return ward_isotropic(g, WardDiffuse, WardSpecular, WardAlpha); }
    #include "environment_light.glsl"
    #include "area_light_brdf.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Frame f = frame_here(fs_in.world_position, fs_in.normal, fs_in.tangent);
        float alpha = clamp(WardAlpha, 0.001, 1.0);
        color = scene_light_sized() ? vec4(LightIrradiance * scene_light_brdf(fs_in.world_position, f.n, f.v, f.t, cross(f.n, f.t), alpha), 1.0)
                                    : radiance(f, visible(f) ? ward_isotropic(f, WardDiffuse, WardSpecular, WardAlpha) : vec3(0.0));
        color.rgb += environment_light(f.n, f.v, f.t, cross(f.n, f.t), alpha);
        fx_capture();
    }
}

technique Lambert { pass p0 { VertexShader = StandardVS; FragmentShader = LambertFS; } }
technique PBR < bool Default = true; > { pass p0 { VertexShader = StandardVS; FragmentShader = PBRFS; } }
technique ModifiedPhong { pass p0 { VertexShader = StandardVS; FragmentShader = ModifiedPhongFS; } }
technique CookTorranceBeckmann { pass p0 { VertexShader = StandardVS; FragmentShader = CookTorranceBeckmannFS; } }
technique AshikhminShirley { pass p0 { VertexShader = StandardVS; FragmentShader = AshikhminShirleyFS; } }
technique CookTorranceGGX { pass p0 { VertexShader = StandardVS; FragmentShader = CookTorranceGGXFS; } }
technique CookTorranceBeckmannSchlick { pass p0 { VertexShader = StandardVS; FragmentShader = CookTorranceBeckmannSchlickFS; } }
technique BlinnPhong { pass p0 { VertexShader = StandardVS; FragmentShader = BlinnPhongFS; } }
technique Ward { pass p0 { VertexShader = StandardVS; FragmentShader = WardFS; } }
// The fit as a plugin (docs/plugins.md): `fxview plugin run effects/brdf/analytic.fx FitAshikhminShirley`
// or the viewer's Plugins tab fits the model to a measured BRDF file and shows it with AshikhminShirleyFit.
plugin FitAshikhminShirley < string Type = "brdf-fit"; string UIName = "Fit Ashikhmin-Shirley to a measured BRDF file";
                             string DataFile = "sample-brdf.csv"; string Model = "ashikhmin-fit";
                             string Targets = "FitDiffuse, FitSpecular, FitExponent"; string Technique = "AshikhminShirleyFit"; >;

technique AshikhminShirleyFit { pass p0 { VertexShader = StandardVS; FragmentShader = AshikhminShirleyFitFS; } }
// Any model of `fxview fit --model` fits the same way; its Targets default to the model's own
// parameters here (GGXDiffuse, GGXF0, GGXAlpha) and its technique to CookTorranceGGX.
plugin FitCookTorranceGGX < string Type = "brdf-fit"; string UIName = "Fit Cook-Torrance (GGX) to a measured BRDF file";
                            string DataFile = "sample-brdf.csv"; string Model = "ggx"; >;

// The BRDF convention (docs/effect-format.md): BRDF() of the model chosen by BrdfModel, for the
// direction grid of brdf-check, brdf-plot and the viewer's BRDF tab. They set BrdfModel to the
// technique in use; `--set BrdfModel=NAME` chooses one explicitly.
uniform int BrdfModel < string UIName = "Model of the BRDF grid"; string UIWidget = "combo"; string UIGroup = "BRDF grid";
                        string UIItems = "Lambert|PBR|ModifiedPhong|CookTorranceBeckmann|AshikhminShirley|AshikhminShirleyFit|CookTorranceGGX|CookTorranceBeckmannSchlick|BlinnPhong|Ward"; > = 1;

vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) {
    Frame f;
    f.n = N;
    f.l = L;
    f.v = V;
    f.t = X;
    f.h = normalize(L + V);
    f.nl = dot(N, L);
    f.nv = dot(N, V);
    f.nh = dot(N, f.h);
    f.vh = dot(V, f.h);
    if (!visible(f)) return vec3(0.0);
    switch (BrdfModel) {
        case 0: return BaseColor / kPi;
        case 1: return metallic_roughness(f, BaseColor, Metallic, Roughness);
        case 2: return modified_phong(f, PhongDiffuse, PhongSpecular, PhongExponent);
        case 3: return cook_torrance_beckmann(f, CTDiffuse, CTSpecular, BeckmannM, Eta, PrintedBeckmann);
        case 4: return ashikhmin_shirley(f, ASDiffuse, ASSpecular, Nu, Nv);
        case 5: return ashikhmin_shirley_fit(f, FitDiffuse, FitSpecular, FitExponent);
        case 6: return cook_torrance_ggx(f, GGXDiffuse, GGXF0, GGXAlpha);
        case 7: return cook_torrance_beckmann_schlick(f, CTSDiffuse, CTSF0, CTSSlope);
        case 8: return blinn_phong(f, BlinnDiffuse, BlinnSpecular, BlinnExponent);
        default: return ward_isotropic(f, WardDiffuse, WardSpecular, WardAlpha);
    }
}

#include "brdf_grid.glsl"
