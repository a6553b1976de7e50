// A scene post-process in the style of the NVIDIA Shader Library's scene_glow: the technique script
// draws the scene (ScriptExternal) into ScnMap, a pass blurs it into BlurMap, a last pass adds the
// blur over the scene in the frame.
#include "include\quad.fxh"

float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "postprocess";
    string ScriptOutput = "color";
    string Script = "Technique=Glow;";
> = 0.8;

float4 ClearColor < string UIWidget = "color"; string UIName = "Background"; > = {0, 0, 0, 0};
float ClearDepth < string UIWidget = "none"; > = 1.0;
float Glowness < string UIName = "Glow strength"; string UIWidget = "slider"; float UIMin = 0.0; float UIMax = 3.0; > = 1.5;
float BlurWidth < string UIName = "Blur width (pixels)"; float UIMin = 1; float UIMax = 16; > = 6;

DECLARE_QUAD_TEX(ScnMap, ScnSamp, "A8R8G8B8")
DECLARE_QUAD_TEX(BlurMap, BlurSamp, "A16B16G16R16F")

float4 BlurPS(QuadVertexOutput IN, uniform sampler2D Source, uniform float Width) : COLOR {
    float4 sum = 0;
    for (int i = -4; i <= 4; i++)
        for (int j = -4; j <= 4; j++)
            sum += tex2D(Source, IN.UV + float2(i, j) * Width / 4.0 * QuadTexelSize);
    return sum / 81.0;
}

float4 CompositePS(QuadVertexOutput IN, uniform sampler2D Scene, uniform sampler2D Blur, uniform float Strength) : COLOR {
    return tex2D(Scene, IN.UV) + Strength * tex2D(Blur, IN.UV);
}

technique Glow <
    string Script =
        "RenderColorTarget0=ScnMap;"
        "RenderDepthStencilTarget=DepthBuffer;"
        "ClearSetColor=ClearColor;"
        "ClearSetDepth=ClearDepth;"
        "Clear=Color;"
        "Clear=Depth;"
        "ScriptExternal=color;"
        "Pass=Blur;"
        "RenderColorTarget0=;"
        "Pass=Composite;";
> {
    pass Blur < string Script = "RenderColorTarget0=BlurMap; Draw=Buffer;"; > {
        VertexShader = compile vs_3_0 ScreenQuadVS();
        ZEnable = false;
        ZWriteEnable = false;
        AlphaBlendEnable = false;
        CullMode = None;
        PixelShader = compile ps_3_0 BlurPS(ScnSamp, BlurWidth);
    }
    pass Composite < string Script = "Draw=Buffer;"; > {
        VertexShader = compile vs_3_0 ScreenQuadVS();
        ZEnable = false;
        CullMode = None;
        PixelShader = compile ps_3_0 CompositePS(ScnSamp, BlurSamp, Glowness);
    }
}
