// expect: 6: uniform 'Hidden' is declared inside a shader block
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
GLSLShader HiddenFS { uniform float Hidden; layout(location = 0) out vec4 c; void main() { c = vec4(Hidden); } }
technique T {
  pass p { VertexShader = StandardVS; FragmentShader = HiddenFS; } }
