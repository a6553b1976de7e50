float4 VS(float4 p : POSITION, uniform float4x3 m[9999]) : POSITION { return p; }
float4 PS(float v : VFACE, float2 q : VPOS, out float d : DEPTH) : COLOR { d = 0.5; return glstate . matrix . mvp[0]; }
sampler S = sampler_state { Texture = <Nowhere>; MinFilter = 99; AddressU = ; };
texture T : RENDERCOLORTARGET < float2 Dimensions = {1e30, -5}; string Format = "A99"; >;
technique X < string Script = "RenderColorTarget0=T;ClearSetColor=Nothing;Clear=Color;ScriptExternal=color;Pass=p;Pass=p;"; > {
  pass p < string Script = "RenderColorTarget9=T;Draw=Buffer;"; > { ZEnable = maybe; CullMode = (1,2,3); ColorWriteEnable = RED|BANANA; VertexShader = compile vs_3_0 VS(1, 2, 3); PixelShader = compile ps_3_0 PS(); }
}
