// Texture examples: a checker-textured Lambert surface, and a mirror that reflects a cube map given
// as one horizontal-cross image. Files come from textures/ (searched after this folder).
#include "standard.glsl"

uniform float Tiling < string UIName = "Tiling"; float UIMin = 1; float UIMax = 16; float UIStep = 1; > = 4.0;
uniform float Ambient < string UIName = "Ambient"; float UIMin = 0; float UIMax = 1; > = 0.1;

// Linear (not mipmapped) filtering: the CPU reference reproduces it exactly (docs/cpu-reference.md),
// for the checker and for the cube map (whose sampler state asks for Linear, not a mipmap filter).
uniform sampler2D Checker < string ResourceName = "checker.png"; string ColorSpace = "sRGB";
                            string Filter = "linear"; string Wrap = "repeat"; >;
texture SkyTexture < string ResourceName = "sky_cross.png"; string ResourceType = "CUBE"; string ColorSpace = "sRGB"; >;
uniform samplerCube Sky = sampler_state { Texture = <SkyTexture>; MinFilter = Linear; MagFilter = Linear; };

GLSLShader CheckerFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        vec3 n = normalize(fs_in.normal);
        vec3 l = normalize(LightPosition - fs_in.world_position);
        vec3 albedo = texture(Checker, fs_in.uv * Tiling).rgb;
        color = vec4(albedo * (Ambient + (1.0 - Ambient) * max(dot(n, l), 0.0)), 1.0);
        fx_capture();
    }
}

GLSLShader MirrorFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        vec3 v = normalize(fs_in.world_position - CameraPosition);
        color = vec4(texture(Sky, reflect(v, normalize(fs_in.normal))).rgb, 1.0);
        fx_capture();
    }
}

technique CheckerLambert {
    pass p0 { VertexShader = StandardVS; FragmentShader = CheckerFS; CullFaceEnable = true; }
}
technique Mirror {
    pass p0 { VertexShader = StandardVS; FragmentShader = MirrorFS; CullFaceEnable = true; }
}
