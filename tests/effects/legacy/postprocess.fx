// A two-pass DirectX 9 post-processing effect driven by SAS scripts: the object is drawn into a
// render target, then a screen quad reads it back inverted.
float Script : STANDARDSGLOBAL <
    string ScriptClass = "scene";
    string ScriptOrder = "postprocess";
    string ScriptOutput = "color";
    string Script = "Technique=Invert;";
> = 0.8;

float4 ClearColor < string UIWidget = "color"; string UIName = "Background"; > = {0.25, 0.5, 0.75, 1.0};
float ClearDepth < string UIWidget = "none"; > = 1.0;
float4x4 WorldViewProjection : WorldViewProjection < string UIWidget = "None"; >;
float3 ObjectColor < string UIWidget = "color"; > = {1.0, 0.5, 0.0};

texture SceneTexture : RENDERCOLORTARGET <
    float2 ViewportRatio = {1.0, 1.0};
    int MipLevels = 1;
    string Format = "A8R8G8B8";
    string UIWidget = "None";
>;
sampler SceneSampler = sampler_state {
    texture = <SceneTexture>;
    AddressU = Clamp;
    AddressV = Clamp;
    MipFilter = None;
    MinFilter = Point;
    MagFilter = Point;
};
texture DepthBuffer : RENDERDEPTHSTENCILTARGET < float2 ViewportRatio = {1.0, 1.0}; string Format = "D24S8"; >;

struct QuadVertex { float4 Position : POSITION; float2 UV : TEXCOORD0; };

QuadVertex QuadVS(float3 Position : POSITION, float3 UV : TEXCOORD0) {
    QuadVertex OUT;
    OUT.Position = float4(Position, 1);
    OUT.UV = UV.xy;
    return OUT;
}

float4 InvertPS(QuadVertex IN, uniform sampler2D Source) : COLOR {
    float4 c = tex2D(Source, IN.UV);
    return float4(1 - c.rgb, 1);
}

float4 ObjectVS(float4 Position : POSITION) : POSITION { return mul(Position, WorldViewProjection); }
float4 ObjectPS() : COLOR { return float4(ObjectColor, 1); }

technique Invert <
    string Script = "RenderColorTarget0=SceneTexture; RenderDepthStencilTarget=DepthBuffer; ClearSetColor=ClearColor;"
                    "ClearSetDepth=ClearDepth; Clear=Color; Clear=Depth; ScriptExternal=color; Pass=Scene; Pass=Post;";
> {
    pass Scene <
        string Script = "RenderColorTarget0=SceneTexture; RenderDepthStencilTarget=DepthBuffer;"
                        "ClearSetColor=ClearColor; ClearSetDepth=ClearDepth; Clear=Color; Clear=Depth; Draw=Geometry;";
    > {
        VertexShader = compile vs_2_0 ObjectVS();
        PixelShader = compile ps_2_0 ObjectPS();
        ZEnable = true;
    }
    pass Post <
        string Script = "RenderColorTarget0=; RenderDepthStencilTarget=; Draw=Buffer;";
    > {
        VertexShader = compile vs_2_0 QuadVS();
        PixelShader = compile ps_2_0 InvertPS(SceneSampler);
        ZEnable = false;
        CullMode = None;
    }
}

technique10 Dx10Only {
    pass p0 { SetVertexShader(CompileShader(vs_4_0, QuadVS())); }
}
