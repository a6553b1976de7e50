// expect: 5: pass p needs a VertexShader and a FragmentShader
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
technique T {
  pass p { VertexShader = StandardVS; }
}
