// expect: 4: incomplete.ftxt:2: FTXT data ends after 1 of 2 texels
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform sampler1D Tex < string ResourceName = "incomplete.ftxt"; string ResourceType = "1D"; >;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
