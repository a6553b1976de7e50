// A 3D texture from an FTXT image of two stacked 1x2 slices; the full-screen pass shows slice 1.
#include "fullscreen.glsl"

uniform sampler3D Volume < string ResourceName = "volume.ftxt"; string ResourceType = "3D"; int Depth = 2;
                           string Filter = "nearest"; string Wrap = "clamp"; >;

GLSLShader SliceFS {
    in vec2 uv;
    layout(location = 0) out vec4 color;
    void main() { color = texture(Volume, vec3(uv, 0.75)); }
}

technique Slice { pass p { VertexShader = FullscreenVS; FragmentShader = SliceFS; Draw = Buffer; } }
