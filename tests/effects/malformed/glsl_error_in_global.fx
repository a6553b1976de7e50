// expect: 6: error
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }

float twice(float x) {
    return x * 2.0 +;
}
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
