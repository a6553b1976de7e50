// expect: 4: malformed number '1.2.3'
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform float X = 1.2.3;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
