// Multi-pass with render targets: pass 1 writes the normal view into Normals (RGBA32F) and the
// texture coordinates into Coords (a second colour target, MRT); pass 2 draws a full-screen
// triangle that reads both with texelFetch and writes 2 * normal colour + coords.b (= 0).
// Doubling is exact in float, so the result equals twice the built-in normal image bit for bit.
#include "standard.glsl"
#include "fullscreen.glsl"

texture Normals : RENDERCOLORTARGET < float2 ViewportRatio = {1.0, 1.0}; string Format = "32F"; >;
texture Coords : RENDERCOLORTARGET < string Format = "RGBA32F"; >;

uniform sampler2D NormalsSampler = sampler_state { Texture = <Normals>; MinFilter = Nearest; MagFilter = Nearest; };
uniform sampler2D CoordsSampler = sampler_state { Texture = Coords; Filter = Nearest; WrapS = Clamp; WrapT = Clamp; };

GLSLShader GBufferFS {
    #include "fragment_inputs.glsl"
    layout(location = 0) out vec4 normal_out;
    layout(location = 1) out vec4 coords_out;
    void main() {
        normal_out = vec4(normalize(fs_in.normal) * 0.5 + 0.5, 1.0);
        coords_out = vec4(fs_in.uv, 0.0, 1.0);
    }
}

GLSLShader CombineFS {
    in vec2 uv;
    layout(location = 0) out vec4 out_color;
    void main() {
        ivec2 texel = ivec2(gl_FragCoord.xy);
        vec4 n = texelFetch(NormalsSampler, texel, 0);
        vec4 c = texelFetch(CoordsSampler, texel, 0);
        out_color = vec4(2.0 * n.rgb + c.b, n.a);
    }
}

technique TwoPass {
    pass gbuffer {
        VertexShader = StandardVS; FragmentShader = GBufferFS;
        RenderColorTarget0 = Normals; RenderColorTarget1 = Coords;
        ClearColor = (0, 0, 0, 0);
    }
    pass combine {
        VertexShader = FullscreenVS; FragmentShader = CombineFS;
        Draw = Buffer; DepthTestEnable = false;
    }
}
