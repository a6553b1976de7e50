// expect: 4: default of vec3 Color has 2 value(s), needs 3
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform vec3 Color = {1.0, 0.5};
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
