// expect: 5: render state ClearColor needs 4 number(s)
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS;
  ClearColor = (0, 0, 0); } }
