// Screen-quad helpers in the style of the NVIDIA Shader Library's Quad.fxh: macros that declare a
// render target texture with its sampler, and the quad vertex program.
#ifndef QUAD_FXH
#define QUAD_FXH

float2 QuadScreenSize : VIEWPORTPIXELSIZE < string UIWidget = "none"; >;
static const float2 QuadTexelSize = float2(1.0, 1.0) / float2(128.0, 128.0);

#define DECLARE_QUAD_TEX(TexName, SampName, PixFmt) \
texture TexName : RENDERCOLORTARGET < \
    float2 ViewportRatio = {1.0, 1.0}; \
    int MipLevels = 1; \
    string Format = PixFmt; \
    string UIWidget = "None"; \
>; \
sampler2D SampName = sampler_state { \
    texture = <TexName>; \
    AddressU = Clamp; \
    AddressV = Clamp; \
    MipFilter = None; \
    MinFilter = Linear; \
    MagFilter = Linear; \
};

texture DepthBuffer : RENDERDEPTHSTENCILTARGET < float2 ViewportRatio = {1.0, 1.0}; string Format = "D24S8"; string UIWidget = "None"; >;

struct QuadVertexOutput {
    float4 Position : POSITION;
    float2 UV : TEXCOORD0;
};

QuadVertexOutput ScreenQuadVS(float3 Position : POSITION, float3 TexCoord : TEXCOORD0) {
    QuadVertexOutput OUT;
    OUT.Position = float4(Position, 1);
    OUT.UV = TexCoord.xy;
    return OUT;
}

#endif
