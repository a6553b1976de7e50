// expect: 5: parameter 'X' declared twice (first at
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform float X = 1.0;
uniform float X = 2.0;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
