// expect: 4: unknown semantic 'WORLDVIEWPROJ' on Wvp
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform mat4 Wvp : WORLDVIEWPROJ;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
