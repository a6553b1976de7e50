// expect: 4: annotation UIMax needs a number
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform float X < string UIMax = "big"; > = 1.0;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
