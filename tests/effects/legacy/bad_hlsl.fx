// A legacy effect whose pixel shader uses an undeclared name on line 7: the error names this line.
float4x4 Wvp : WorldViewProjection;
float4 VS(float4 P : POSITION) : POSITION { return mul(P, Wvp); }

float4 PS() : COLOR {
    float4 c = float4(1, 0, 0, 1);
    return c * undeclaredGain;
}

technique Broken { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
