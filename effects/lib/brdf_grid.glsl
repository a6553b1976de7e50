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
uniform int FxGridMode < string UIName = "Grid layout"; string UIWidget = "combo"; string UIItems = "incidence tiles|plane of incidence|half-difference slice|hemisphere";
                         string UIGroup = "BRDF grid"; > = 0;
uniform float FxIncidence < string UIName = "Incidence (plane)"; float UIMin = 0; float UIMax = 89; string UIUnits = "deg";
                            string UIGroup = "BRDF grid"; > = 30.0;
// Mode 2 (`--view slice`): Rusinkiewicz's (θh, θd) image at φd = FxPhiD, θh along x and θd along y,
// 0-90° each (black where l or v is below the surface). Mode 3 (`--view lobe`): the hemisphere for
// θi = FxIncidence, φo along x (0-360°) and θo along y (0-90°), in equal angle steps.
uniform float FxPhiD < string UIName = "Difference azimuth (slice)"; float UIMin = 0; float UIMax = 180; string UIUnits = "deg";
                       string UIGroup = "BRDF grid"; > = 90.0;

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
        if (FxGridMode == 3) {
            float phi = radians(360.0 * gl_FragCoord.x / FxViewportSize.x), theta_o = radians(90.0 * gl_FragCoord.y / FxViewportSize.y);
            float theta_i = radians(FxIncidence);
            vec3 l = vec3(sin(theta_i), 0.0, cos(theta_i)), v = vec3(sin(theta_o) * cos(phi), sin(theta_o) * sin(phi), cos(theta_o));
            color = vec4(FxSwapArguments ? vec3(BRDF(v, l, n, x, y)) : vec3(BRDF(l, v, n, x, y)), 1.0);
            return;
        }
        if (FxGridMode == 1) {
            float theta_o = radians(-90.0 + 180.0 * gl_FragCoord.x / FxViewportSize.x), theta_i = radians(FxIncidence);
            vec3 l = vec3(sin(theta_i), 0.0, cos(theta_i)), v = vec3(sin(theta_o), 0.0, cos(theta_o));
            color = vec4(FxSwapArguments ? vec3(BRDF(v, l, n, x, y)) : vec3(BRDF(l, v, n, x, y)), 1.0);
            return;
        }
        int tile = (p.y / kFxGridTile) * kFxGridTilesX + p.x / kFxGridTile;
        if (tile >= kFxGridIncidences) {
            color = vec4(0.0);
            return;
        }
        ivec2 q = p % kFxGridTile;
        float theta_i = radians(1.0 + 2.0 * float(tile));
        float mu = (float(q.y) + 0.5) / float(kFxGridTile);
        float phi = 6.28318530718 * (float(q.x) + 0.5) / float(kFxGridTile);
        float s = sqrt(max(1.0 - mu * mu, 0.0));
        vec3 l = vec3(sin(theta_i), 0.0, cos(theta_i)), v = vec3(s * cos(phi), s * sin(phi), mu);
        color = vec4(FxSwapArguments ? vec3(BRDF(v, l, n, x, y)) : vec3(BRDF(l, v, n, x, y)), 1.0);
    }
}

technique BrdfGrid < string UIName = "BRDF over a direction grid (brdf-check)";
                     string UIHelp = "f(l, v) for 45 incidence angles, each tile all outgoing directions: what brdf-check sums"; >
    { pass p0 { Draw = Buffer; VertexShader = FullscreenVS; FragmentShader = FxBrdfGridFS; } }
