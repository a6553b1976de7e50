// The built-in debug views of the original ShaderViewer (seed 002 ch. 4.1), applicable to any
// object: every vector is mapped to colour by eq. 55, normalize(v) * 0.5 + 0.5.
// `Plain` is a simple Lambert in linear RGB, for comparison with the effects.
#include "standard.glsl"

uniform vec3 PlainColor < string UIName = "Plain colour"; string UIWidget = "color"; string UIGroup = "Plain"; > = {0.8, 0.8, 0.8};
uniform float Ambient < string UIName = "Ambient"; float UIMin = 0.0; float UIMax = 1.0; float UIStep = 0.01;
                        string UIGroup = "Plain"; string UIHelp = "Light that reaches faces turned away from the light"; > = 0.05;

vec3 map_vector(vec3 v) { return normalize(v) * 0.5 + 0.5; }  // eq. 55

GLSLShader NormalsFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 out_color;
    void main() { out_color = vec4(map_vector(fs_in.normal), 1.0); fx_capture(); }
}

GLSLShader TexCoordsFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 out_color;
    void main() { out_color = vec4(fs_in.uv, 0.0, 1.0); fx_capture(); }
}

GLSLShader VectorToCameraFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 out_color;
    void main() { out_color = vec4(map_vector(CameraPosition - fs_in.world_position), 1.0); fx_capture(); }
}

GLSLShader VectorToLightFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 out_color;
    void main() { out_color = vec4(map_vector(LightPosition - fs_in.world_position), 1.0); fx_capture(); }
}

GLSLShader PlainFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 out_color;
    void main() {
        vec3 n = normalize(fs_in.normal);
        vec3 l = normalize(LightPosition - fs_in.world_position);
        out_color = vec4(PlainColor * (Ambient + (1.0 - Ambient) * max(dot(n, l), 0.0)), 1.0);
        fx_capture();
    }
}

technique Normals < string UIHelp = "World-space normal as colour"; > {
    pass p0 { VertexShader = StandardVS; FragmentShader = NormalsFS; CullFaceEnable = false; }
}
technique TexCoords {
    pass p0 { VertexShader = StandardVS; FragmentShader = TexCoordsFS; CullFaceEnable = false; }
}
technique VectorToCamera {
    pass p0 { VertexShader = StandardVS; FragmentShader = VectorToCameraFS; CullFaceEnable = false; }
}
technique VectorToLight {
    pass p0 { VertexShader = StandardVS; FragmentShader = VectorToLightFS; CullFaceEnable = false; }
}
technique Plain {
    pass p0 { VertexShader = StandardVS; FragmentShader = PlainFS; CullFaceEnable = true; CullFace = Back; }
}
