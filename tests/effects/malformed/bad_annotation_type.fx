// expect: 4: annotation UIMin is declared string but its value is not a string
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform float X < string UIMin = 0.5; > = 1.0;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
