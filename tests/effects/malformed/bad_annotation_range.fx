// expect: 4: UIMin 2.000000 exceeds UIMax 1.000000
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform float X < float UIMin = 2; float UIMax = 1; > = 1.0;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
