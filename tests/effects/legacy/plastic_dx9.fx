/*
   A DirectX 9 effect in the style of the NVIDIA Shader Library (2008): row vectors, mul(v, M),
   SAS semantics, a texture object with a sampler_state, DX9 render states.
*/
float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "object";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=Main;";
> = 0.8;

float4x4 WorldITXf : WorldInverseTranspose < string UIWidget = "None"; >;
float4x4 WvpXf : WorldViewProjection < string UIWidget = "None"; >;
float4x4 WorldXf : World < string UIWidget = "None"; >;
float4x4 ViewIXf : ViewInverse < string UIWidget = "None"; >;

float3 Lamp0Pos : Position <
    string Object = "PointLight0";
    string UIName = "Lamp 0 Position";
    string Space = "World";
> = {-0.5f, 2.0f, 1.25f};

float3 SurfaceColor : DIFFUSE <
    string UIName = "Surface";
    string UIWidget = "Color";
> = {0.9f, 0.4f, 0.1f};

float SpecExpon : SpecularPower <
    string UIWidget = "slider";
    float UIMin = 1.0;
    float UIMax = 128.0;
    float UIStep = 1.0;
    string UIName = "Specular Power";
> = 30.0;

texture ColorTexture <
    string ResourceName = "default_color.dds";
    string UIName = "Diffuse Texture";
    string ResourceType = "2D";
>;

sampler2D ColorSampler = sampler_state {
    Texture = <ColorTexture>;
    MinFilter = Linear;
    MipFilter = Linear;
    MagFilter = Linear;
    AddressU = Wrap;
    AddressV = Clamp;
};

struct appdata {
    float3 Position : POSITION;
    float4 UV : TEXCOORD0;
    float4 Normal : NORMAL;
};

struct vertexOutput {
    float4 HPosition : POSITION;
    float2 UV : TEXCOORD0;
    float3 LightVec : TEXCOORD1;
    float3 WorldNormal : TEXCOORD2;
    float3 WorldView : TEXCOORD3;
};

vertexOutput std_VS(appdata IN, uniform float4x4 WorldITXf, uniform float4x4 WorldXf, uniform float4x4 ViewIXf,
                    uniform float4x4 WvpXf, uniform float3 LampPos) {
    vertexOutput OUT = (vertexOutput)0;
    OUT.WorldNormal = mul(IN.Normal, WorldITXf).xyz;
    float4 Po = float4(IN.Position.xyz, 1);
    float3 Pw = mul(Po, WorldXf).xyz;
    OUT.LightVec = (LampPos - Pw);
    OUT.UV = IN.UV.xy;
    OUT.WorldView = normalize(ViewIXf[3].xyz - Pw);
    OUT.HPosition = mul(Po, WvpXf);
    return OUT;
}

float4 std_PS(vertexOutput IN, uniform float3 Color, uniform float Exponent) : COLOR {
    float3 Ln = normalize(IN.LightVec);
    float3 Nn = normalize(IN.WorldNormal);
    float3 Vn = normalize(IN.WorldView);
    float3 Hn = normalize(Vn + Ln);
    float4 lit = lit(dot(Ln, Nn), dot(Hn, Nn), Exponent);
    float3 texColor = tex2D(ColorSampler, IN.UV).rgb;
    return float4(Color * texColor * (lit.y + 0.1) + lit.zzz * 0.5, 1);
}

technique Main <
    string Script = "Pass=p0;";
> {
    pass p0 <
        string Script = "Draw=geometry;";
    > {
        VertexShader = compile vs_3_0 std_VS(WorldITXf, WorldXf, ViewIXf, WvpXf, Lamp0Pos);
        ZEnable = true;
        ZWriteEnable = true;
        ZFunc = LessEqual;
        AlphaBlendEnable = false;
        CullMode = None;
        PixelShader = compile ps_3_0 std_PS(SurfaceColor, SpecExpon);
    }
}
