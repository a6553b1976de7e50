// Two passes: the first writes Value, the second adds Value again with additive blending.
// With Value = 0.25 every covered pixel must hold exactly 0.5 (sums of powers of two are exact).
#include "standard.glsl"

uniform float Value = 0.25;

GLSLShader ConstantFS {
    layout(location = 0) out vec4 out_color;
    void main() { out_color = vec4(Value, Value, Value, 1.0); }
}

technique Additive {
    pass first { VertexShader = StandardVS; FragmentShader = ConstantFS; }
    pass second {
        VertexShader = StandardVS; FragmentShader = ConstantFS;
        DepthFunc = LEqual; DepthMask = false;
        BlendEnable = true; BlendFunc = (One, One); ColorMask = (true, true, true, false);
    }
}
