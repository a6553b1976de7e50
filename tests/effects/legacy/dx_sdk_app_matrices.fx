// A DirectX SDK sample driven by its application: the matrices have no semantics, the application set
// them by name (ID3DXEffect::SetMatrix("g_mWorldViewProjection", ...)). fxview supplies them by name.
float4x4 g_mWorldViewProjection;
float4x4 g_mWorld;
float3 g_LightPos : Position < string Object = "PointLight0"; > = {1, 2, 3};
texture g_MeshTexture < string ResourceName = "missing_tiger.bmp"; string UIName = "Mesh texture"; >;
sampler MeshTextureSampler = sampler_state { Texture = <g_MeshTexture>; MipFilter = Linear; MinFilter = Linear; MagFilter = Linear; };

void RenderSceneVS(float4 Pos : POSITION, float3 Normal : NORMAL, float2 Tex : TEXCOORD0,
                   out float4 oPos : POSITION, out float3 oNormal : TEXCOORD1, out float3 oToLight : TEXCOORD2, out float2 oTex : TEXCOORD0) {
    oPos = mul(Pos, g_mWorldViewProjection);
    oNormal = mul(Normal, (float3x3)g_mWorld);
    oToLight = g_LightPos - mul(Pos, g_mWorld).xyz;
    oTex = Tex;
}

float4 RenderScenePS(float3 Normal : TEXCOORD1, float3 ToLight : TEXCOORD2, float2 Tex : TEXCOORD0) : COLOR0 {
    return float4(tex2D(MeshTextureSampler, Tex).rgb * saturate(dot(normalize(Normal), normalize(ToLight))), 1);
}

technique RenderScene {
    pass P0 {
        VertexShader = compile vs_2_0 RenderSceneVS();
        PixelShader = compile ps_2_0 RenderScenePS();
    }
}
