// expect: 4: default of Scale must be numeric, not a string
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform float Scale = "large";
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
