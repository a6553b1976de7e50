// expect: 5: pass p renders into 'Buffer', which is not declared
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
technique T {
  pass p { VertexShader = StandardVS; FragmentShader = FS; RenderColorTarget0 = Buffer; }
}
