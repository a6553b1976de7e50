// expect: 5: error
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
GLSLShader BrokenFS {
    layout(location = 0) out vec4 c; void main() { c = undefined_thing; }
}
technique T { pass p { VertexShader = StandardVS; FragmentShader = BrokenFS; } }
