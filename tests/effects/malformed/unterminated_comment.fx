// expect: 4: unterminated comment
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
/* this comment never ends
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
