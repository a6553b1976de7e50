// A clear inside the loop body: each iteration clears, then adds Step once; the frame holds Step
// whatever Count (at least 1) is, and the background for 0 (copies beyond Count are skipped with
// their clears).
#include "include\quad.fxh"

float Script : STANDARDSGLOBAL <
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "postprocess";
    string ScriptOutput = "color";
    string Script = "Technique=Accumulate;";
> = 0.8;

int Count < string UIName = "Passes"; int UIMin = 0; int UIMax = 10; > = 3;
float4 ClearColor < string UIWidget = "color"; string UIName = "Background"; > = {0, 0, 0, 1};
float Step < string UIName = "Added per pass"; > = 0.1;

float4 AddPS(QuadVertexOutput IN) : COLOR { return float4(Step, Step, Step, 0); }

technique Accumulate < string Script = "LoopByCount=Count; ClearSetColor=ClearColor; Clear=Color; Pass=Add; LoopEnd;"; > {
    pass Add < string Script = "Draw=Buffer;"; > {
        VertexShader = compile vs_3_0 ScreenQuadVS();
        ZEnable = false;
        CullMode = None;
        AlphaBlendEnable = true;
        SrcBlend = One;
        DestBlend = One;
        PixelShader = compile ps_3_0 AddPS();
    }
}
