float4x4 W : WorldViewProjection;
int N = 64;
float4 VS(float4 p : POSITION) : POSITION { return mul(p, W); }
float4 PS() : COLOR { return 1; }
technique T < string Script = "LoopByCount=N;LoopByCount=N;LoopByCount=N;Pass=p;LoopEnd;LoopEnd;LoopEnd;LoopEnd;LoopEnd;Pass=missing;"; > {
  pass p { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); }
}
