// Two passes: the first writes Value, the second adds Value again with additive blending.
// With Value = 0.25 every covered pixel must hold exactly 0.5 (sums of powers of two are exact).
#include "standard.glsl"

uniform float Value = 0.25;
uniform uint One = 1u;    // unsigned and bool parameters take their own GL setters:
uniform bool Enabled = true;  // a wrong one leaves them 0 and the sums below 0

GLSLShader ConstantFS {
    layout(location = 0) out vec4 out_color;
    void main() {
        float v = Enabled ? Value * float(One) : 0.0;
        out_color = vec4(v, v, v, 1.0);
    }
}

technique Additive {
    pass first { VertexShader = StandardVS; FragmentShader = ConstantFS; }
    pass second {
        VertexShader = StandardVS; FragmentShader = ConstantFS;
        DepthFunc = LEqual; DepthMask = false;
        BlendEnable = true; BlendFunc = (One, One); ColorMask = (true, true, true, false);
    }
}
