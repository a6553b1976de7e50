// The direction grid of `fxview brdf-check`, `fxview brdf-plot` and the viewer's BRDF tab, for any
// effect that defines vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) (unit vectors to the light and
// the eye, the normal, the tangent and the bitangent) and includes this file after it: every .brdf
// file does (brdf_file.glsl), and so can an .fx effect (docs/effect-format.md).
#pragma once
// Tile t (row-major, kFxGridTilesX tiles a row) holds incidence θi = 1° + 2° t in the plane of the
// tangent (φi = 0); within it, pixel (a, b) is the outgoing direction with cos θo = (b + ½) / kFxGridTile
// and φo = 2π (a + ½) / kFxGridTile: equal solid angle per pixel, so the albedo is a plain sum.
// FxSwapArguments evaluates f(V, L) instead, for the reciprocity check.
#include "fullscreen.glsl"
const int kFxGridTile = 256, kFxGridTilesX = 9, kFxGridIncidences = 45;
uniform vec4 FxViewportSize : VIEWPORTPIXELSIZE;
uniform bool FxSwapArguments < string UIName = "Swap L and V"; string UIGroup = "BRDF grid";
                               string UIHelp = "Evaluate f(V, L) instead of f(L, V) (reciprocity check)"; > = false;
// Mode 1 (`fxview brdf-plot --view polar`): one row across the plane of incidence instead, θo from
// -90° (mirror side) to 90° (the light's side) over the target's width, for θi = FxIncidence.
uniform int FxGridMode < string UIName = "Grid layout"; string UIWidget = "combo"; string UIItems = "incidence tiles|plane of incidence|half-difference slice|hemisphere|sampled directions";
                         string UIGroup = "BRDF grid"; > = 0;
uniform float FxIncidence < string UIName = "Incidence (plane)"; float UIMin = 0; float UIMax = 89; string UIUnits = "deg";
                            string UIGroup = "BRDF grid"; > = 30.0;
// Mode 2 (`--view slice`): Rusinkiewicz's (θh, θd) image at φd = FxPhiD, θh along x and θd along y,
// 0-90° each (black where l or v is below the surface). Mode 3 (`--view lobe`): the hemisphere for
// θi = FxIncidence, φo along x (0-360°) and θo along y (0-90°), in equal angle steps.
uniform float FxPhiD < string UIName = "Difference azimuth (slice)"; float UIMin = 0; float UIMax = 180; string UIUnits = "deg";
                       string UIGroup = "BRDF grid"; > = 90.0;
// The azimuth of incidence φi in modes 0, 1, 3 and 4 (`--phi-i`): l is turned about the normal by it
// (the plane of incidence of mode 1 with it); 0 is the tangent's direction.
uniform float FxPhiI < string UIName = "Incidence azimuth"; float UIMin = 0; float UIMax = 360; string UIUnits = "deg";
                       string UIGroup = "BRDF grid"; > = 0.0;
// Mode 4 (brdf-check, app/brdf_check.cpp): tile t of side FxViewportSize.x / kFxGridTilesX holds
// θi = 1° + 2° t; its first FxSampleSide² pixels are outgoing directions drawn by one strategy from
// the midpoints of a FxSampleSide² grid shifted by FxSampleShift: 0 cosine-weighted, 1 uniform over the hemisphere, 2 half vectors of a GGX
// lobe of width FxSampleAlpha reflected about (v = 2 (l·h) h − l). Alpha is 0 where v is below the
// surface. The CPU knows the same directions and weighs them (multiple importance sampling).
// Strategy 3 is the file's own sampler (a .brdf's isFunc: sampleBRDF and pdfBRDF, declared before
// this file, with FX_BRDF_IS_FUNC defined); FxSampleOutput 1 writes each sample's direction v (rgb)
// and the file's density for it (alpha, 0 without a sampler of its own) instead of f.
uniform int FxSampleStrategy < string UIName = "Sampling strategy"; string UIWidget = "combo"; string UIItems = "cosine|uniform|half-vector|file's own";
                               string UIGroup = "BRDF grid"; > = 0;
uniform int FxSampleOutput < string UIName = "Sample output"; string UIWidget = "combo"; string UIItems = "BRDF value|direction and file's density";
                             string UIGroup = "BRDF grid"; > = 0;
uniform float FxSampleAlpha < string UIName = "Sampled lobe width"; float UIMin = 0.001; float UIMax = 1; string UIGroup = "BRDF grid"; > = 0.1;
uniform vec2 FxSampleShift < string UIName = "Sample shift"; string UIGroup = "BRDF grid"; > = vec2(0.0, 0.0);
uniform int FxSampleSide < string UIName = "Sample grid"; int UIMin = 1; int UIMax = 4096; string UIGroup = "BRDF grid"; > = 64;

vec3 fx_incidence(float theta_degrees) {
    float t = radians(theta_degrees), p = radians(FxPhiI);
    return vec3(sin(t) * cos(p), sin(t) * sin(p), cos(t));
}

#ifdef FX_BRDF_IS_FUNC
vec3 fx_file_sample(vec3 l, vec3 n, vec3 x, vec3 y, vec2 u) { return sampleBRDF(l, n, x, y, u); }
float fx_file_pdf(vec3 v, vec3 l, vec3 n, vec3 x, vec3 y) { return pdfBRDF(v, l, n, x, y); }
#else
vec3 fx_file_sample(vec3 l, vec3 n, vec3 x, vec3 y, vec2 u) { return vec3(0.0, 0.0, -1.0); }
float fx_file_pdf(vec3 v, vec3 l, vec3 n, vec3 x, vec3 y) { return 0.0; }
#endif

vec3 fx_sampled_direction(vec3 l, vec2 u) {
    float phi = 6.28318530718 * u.y;
    if (FxSampleStrategy == 3) return fx_file_sample(l, vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), u);
    if (FxSampleStrategy == 0) {
        float r = sqrt(u.x);
        return vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - u.x, 0.0)));
    }
    if (FxSampleStrategy == 1) {
        float s = sqrt(max(1.0 - u.x * u.x, 0.0));
        return vec3(s * cos(phi), s * sin(phi), u.x);
    }
    float a2 = FxSampleAlpha * FxSampleAlpha;
    float c2 = (1.0 - u.x) / (1.0 + (a2 - 1.0) * u.x);
    float sh = sqrt(max(1.0 - c2, 0.0));
    vec3 h = vec3(sh * cos(phi), sh * sin(phi), sqrt(c2));
    return 2.0 * dot(l, h) * h - l;
}

GLSLShader FxBrdfGridFS {
    layout(location = 0) out vec4 color;
    // For GPU-vs-CPU comparisons (docs/cpu-reference.md): coverage in attachment 1, and in attachment
    // 5 the fragment's position and the viewport's size, from which a reference rebuilds the directions.
    layout(location = 1) out vec4 fx_capture_position;
    layout(location = 5) out vec4 fx_capture_footprint;
    void main() {
        fx_capture_position = vec4(0.0, 0.0, 0.0, 1.0);
        fx_capture_footprint = vec4(gl_FragCoord.xy, FxViewportSize.xy);
        ivec2 p = ivec2(gl_FragCoord.xy);
        vec3 n = vec3(0.0, 0.0, 1.0), x = vec3(1.0, 0.0, 0.0), y = vec3(0.0, 1.0, 0.0);
        if (FxGridMode == 2) {
            float theta_h = radians(90.0 * gl_FragCoord.x / FxViewportSize.x), theta_d = radians(90.0 * gl_FragCoord.y / FxViewportSize.y);
            float phi_d = radians(FxPhiD);
            vec3 d = vec3(sin(theta_d) * cos(phi_d), sin(theta_d) * sin(phi_d), cos(theta_d));
            vec3 l = vec3(d.x * cos(theta_h) + d.z * sin(theta_h), d.y, -d.x * sin(theta_h) + d.z * cos(theta_h));
            vec3 h = vec3(sin(theta_h), 0.0, cos(theta_h));
            vec3 v = 2.0 * dot(l, h) * h - l;
            color = vec4(l.z > 0.0 && v.z > 0.0 ? (FxSwapArguments ? vec3(BRDF(v, l, n, x, y)) : vec3(BRDF(l, v, n, x, y))) : vec3(0.0), 1.0);
            return;
        }
        if (FxGridMode == 4) {
            int side = int(FxViewportSize.x) / kFxGridTilesX;
            int tile = (p.y / side) * kFxGridTilesX + p.x / side;
            if (tile >= kFxGridIncidences) {
                color = vec4(0.0);
                return;
            }
            ivec2 cell = p % side;
            vec3 l = fx_incidence(1.0 + 2.0 * float(tile));
            vec3 v = fx_sampled_direction(l, fract((vec2(cell) + 0.5) / float(FxSampleSide) + FxSampleShift));
            if (cell.x >= FxSampleSide || cell.y >= FxSampleSide) v = vec3(0.0, 0.0, -1.0);
            if (FxSampleOutput == 1) {
                color = vec4(v, v.z > 0.0 ? fx_file_pdf(normalize(v), l, n, x, y) : 0.0);
                return;
            }
            if (v.z <= 0.0) {
                color = vec4(0.0);
                return;
            }
            v = normalize(v);
            color = vec4(FxSwapArguments ? vec3(BRDF(v, l, n, x, y)) : vec3(BRDF(l, v, n, x, y)), 1.0);
            return;
        }
        if (FxGridMode == 3) {
            float phi = radians(360.0 * gl_FragCoord.x / FxViewportSize.x), theta_o = radians(90.0 * gl_FragCoord.y / FxViewportSize.y);
            vec3 l = fx_incidence(FxIncidence), v = vec3(sin(theta_o) * cos(phi), sin(theta_o) * sin(phi), cos(theta_o));
            color = vec4(FxSwapArguments ? vec3(BRDF(v, l, n, x, y)) : vec3(BRDF(l, v, n, x, y)), 1.0);
            return;
        }
        if (FxGridMode == 1) {
            float theta_o = radians(-90.0 + 180.0 * gl_FragCoord.x / FxViewportSize.x), phi_i = radians(FxPhiI);
            vec3 l = fx_incidence(FxIncidence), v = vec3(sin(theta_o) * cos(phi_i), sin(theta_o) * sin(phi_i), cos(theta_o));
            color = vec4(FxSwapArguments ? vec3(BRDF(v, l, n, x, y)) : vec3(BRDF(l, v, n, x, y)), 1.0);
            return;
        }
        int tile = (p.y / kFxGridTile) * kFxGridTilesX + p.x / kFxGridTile;
        if (tile >= kFxGridIncidences) {
            color = vec4(0.0);
            return;
        }
        ivec2 q = p % kFxGridTile;
        float mu = (float(q.y) + 0.5) / float(kFxGridTile);
        float phi = 6.28318530718 * (float(q.x) + 0.5) / float(kFxGridTile);
        float s = sqrt(max(1.0 - mu * mu, 0.0));
        vec3 l = fx_incidence(1.0 + 2.0 * float(tile)), v = vec3(s * cos(phi), s * sin(phi), mu);
        color = vec4(FxSwapArguments ? vec3(BRDF(v, l, n, x, y)) : vec3(BRDF(l, v, n, x, y)), 1.0);
    }
}

technique BrdfGrid < string UIName = "BRDF over a direction grid (brdf-check)";
                     string UIHelp = "f(l, v) for 45 incidence angles, each tile all outgoing directions: what brdf-check sums"; >
    { pass p0 { Draw = Buffer; VertexShader = FullscreenVS; FragmentShader = FxBrdfGridFS; } }
