// expect: 5: expected 'pass' or '}' in technique T, found 'passage'
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
technique T {
  passage p { VertexShader = StandardVS; FragmentShader = FS; }
}
