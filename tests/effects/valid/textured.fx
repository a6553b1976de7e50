// Samples a texture file named by ResourceName (relative to this file) with nearest filtering on
// a full-screen triangle: the output is the texture, texel for texel (tests/test_effect.cpp).
#include "fullscreen.glsl"

uniform sampler2D Image < string ResourceName = "pattern.ftxt"; string ResourceType = "2D";
                          string Filter = "nearest"; string Wrap = "clamp"; >;
uniform sampler2D Quantised < string ResourceName = "pattern.ftxt"; string Format = "8";
                              string Filter = "nearest"; >;

GLSLShader ShowFS {
    in vec2 uv;
    layout(location = 0) out vec4 out_color;
    layout(location = 1) out vec4 quantised;
    void main() {
        out_color = texture(Image, uv);
        quantised = texture(Quantised, uv);
    }
}

technique Show {
    pass p { VertexShader = FullscreenVS; FragmentShader = ShowFS; Draw = Buffer; DepthTestEnable = false; }
}
