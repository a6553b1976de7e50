// DirectX SDK and RenderMonkey idioms: a float4x3 world matrix, RenderMonkey's ViewPosition, an
// untyped sampler read with texCUBE, the ps_3_0 registers VFACE and VPOS, a parameter bound by the
// compile statement without `uniform`, DirectX 8's `string name` texture annotation, DX10 state
// objects next to a technique10.
float4x3 World43 : World;
float4x4 ViewProj : ViewProjection;
float4 ViewPos : ViewPosition;
float Reflectivity < string UIName = "Reflectivity"; float4 UIMin = float4(0, 0, 0, 0); float4 UIMax = float4(1, 1, 1, 1); > = 0.5;

texture EnvTex < string name = "missing_sky.dds"; >;
sampler Env = sampler_state { Texture = <EnvTex>; MinFilter = Linear; MagFilter = Linear; MipFilter = Linear; };

RasterizerState NoCull { CullMode = NONE; };
BlendState NoBlend { BlendEnable[0] = FALSE; };

struct VSOut {
    float4 Pos : POSITION;
    float3 Normal : TEXCOORD0;
    float3 ToEye : TEXCOORD1;
};

VSOut VS(float4 Pos : POSITION, float3 Normal : NORMAL) {
    VSOut o;
    float3 world = mul(Pos, World43);
    o.Pos = mul(float4(world, 1), ViewProj);
    o.Normal = mul(Normal, (float3x3)World43);
    o.ToEye = ViewPos.xyz - world;
    return o;
}

float4 PS(VSOut i, float face : VFACE, float2 pixel : VPOS, float amount) : COLOR {
    float3 n = normalize(i.Normal) * face;
    float3 r = reflect(-normalize(i.ToEye), n);
    float3 sky = texCUBE(Env, r).rgb;
    float3 base = float3(0.3, 0.5, 0.8) * saturate(n.z * 0.5 + 0.5) + 0.0 * pixel.x;
    return float4(lerp(base, sky, amount), 1);
}

technique Reflect { pass p0 { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(Reflectivity); } }

technique10 Reflect10 {
    pass p0 {
        SetRasterizerState(NoCull);
        SetBlendState(NoBlend, float4(0, 0, 0, 0), 0xFFFFFFFF);
        SetVertexShader(CompileShader(vs_4_0, VS()));
        SetPixelShader(CompileShader(ps_4_0, PS(Reflectivity)));
    }
}
