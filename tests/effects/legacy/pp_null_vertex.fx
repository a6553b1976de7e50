// In the style of the DirectX SDK's post-processing samples (PP_ColorBrightPass.fx and its kin): the
// passes have no vertex shader (VertexShader = null, DirectX's fixed-function vertex stage) and a
// pixel shader reading TEXCOORD0; the application sets the source texture by name.
texture g_txSrcColor < string ResourceName = "missing_scene.png"; >;
sampler2D g_samSrcColor = sampler_state { Texture = <g_txSrcColor>; AddressU = Clamp; AddressV = Clamp; MinFilter = Point; MagFilter = Linear; };
static const float BRIGHT_THRESHOLD = 0.5f;

float4 BrightPassFilter(in float2 Tex : TEXCOORD0, in float4 Diffuse : COLOR0) : COLOR0 {
    float3 color = tex2D(g_samSrcColor, Tex).rgb * Diffuse.rgb;
    return float4(max(color - BRIGHT_THRESHOLD, 0.0) * 4.0 + float3(Tex, 0.25), 1.0f);
}

technique PostProcess < string Parameter0 = "Luminance"; float4 Parameter0Def = float4(0.08f, 0, 0, 0); > {
    pass p0 < float fScaleX = 0.5f; float fScaleY = 0.5f; > {
        VertexShader = null;
        PixelShader = compile ps_2_0 BrightPassFilter();
        ZEnable = false;
    }
}
