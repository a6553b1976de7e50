// expect: 5: technique 'T' defined twice
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
