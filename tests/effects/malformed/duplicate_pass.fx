// expect: 6: pass 'p' defined twice in technique T
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
technique T {
  pass p { VertexShader = StandardVS; FragmentShader = FS; }
  pass p { VertexShader = StandardVS; FragmentShader = FS; }
}
