// expect: 5: plugin Fit needs a Type annotation
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
plugin Fit < string Data = "Measured"; >;
