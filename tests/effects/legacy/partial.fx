// Two techniques, one of which cannot be translated (its compile statement passes an argument the
// function does not take, line 8): the effect opens with the other and names the broken one.
float4x4 Wvp : WorldViewProjection;
float4 VS(float4 P : POSITION) : POSITION { return mul(P, Wvp); }
float4 PS() : COLOR { return float4(0.2, 0.4, 0.6, 1); }

technique Broken {
    pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(1.0); }
}
technique Good {
    pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); }
}
