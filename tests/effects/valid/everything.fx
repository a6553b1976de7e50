// A valid effect that uses every feature the parser accepts; tests/test_effect.cpp checks the result.
#include "standard.glsl"
#include "standard.glsl"   // #pragma once: the second include adds nothing

uniform float Roughness < string UIName = "Roughness"; string UIWidget = "Slider"; float UIMin = 0.0;
                          float UIMax = 1.0; float UIStep = 0.01; string UIGroup = "Surface"; int UIOrder = 2;
                          string UIUnits = "1"; string UIHelp = "Microfacet roughness"; > = 0.5;
uniform vec3 Tint < string SasUiLabel = "Tint"; string SasUiControl = "ColorPicker"; float SasUiMin = 0;
                    float SasUiMax = 1; int SasUiSteps = 100; > = vec3(0.25);
uniform int Mode < string label = "Mode"; string widget = "combo"; string items = "off|on|auto"; > = 1;
uniform bool Enabled = true;
uniform vec4 Offsets[2] = {1, 2, 3, 4, 5, 6, 7, 8};
uniform mat4 Wvp : WorldViewProjection;
uniform mat4 WorldViewIT : WORLDVIEWINVERSETRANSPOSE;
uniform vec4 Viewport : VIEWPORTPIXELSIZE;
uniform float Time : TIME;

#define SCALE 2.0
const float kHalf = 0.5;
struct Pair { float a; float b; };
float scaled(float x) { return x * SCALE * kHalf; }

GLSLShader ColorFS {
    #include "fragment_inputs.glsl"
    layout(location = 0) out vec4 out_color;
    void main() {
        Pair p = Pair(Roughness, scaled(1.0));
        out_color = vec4(Tint * p.b + 0.0 * (Offsets[1].x + float(Mode) + Time + Viewport.x + Wvp[0][0] + WorldViewIT[0][0]), Enabled ? 1.0 : 0.0);
    }
}

technique Main < string UIHelp = "first"; > {
    pass base {
        VertexProgram = compile glslv StandardVS();
        FragmentProgram = compile glslf ColorFS();
        DepthTestEnable = true; DepthMask = false; DepthFunc = LEqual;
        CullMode = Back; BlendEnable = true; BlendFunc = (SrcAlpha, OneMinusSrcAlpha);
        BlendEquation = Add; ColorMask = (true, true, false, true); PolygonMode = Fill;
        ClearColor = (0.1, 0.2, 0.3, 1.0); ClearDepth = 1.0;
    }
    pass { VertexShader = StandardVS; PixelShader = ColorFS; depthtestenable = false; }
}
