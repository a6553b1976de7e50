// Two declarations of one name: HLSL refuses them, and glslang would crash on this pair.
float4x4 Wvp : WorldViewProjection;
float4 Tint = {1, 0, 0, 1};
float Tint = 0.5;
float4 VS(float4 P : POSITION) : POSITION { return mul(P, Wvp); }
float4 PS() : COLOR { return Tint; }
technique T { pass p { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
