// expect: 4: cross.ftxt: a horizontal cube cross must be 4x3 equal squares
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform samplerCube Sky < string ResourceName = "cross.ftxt"; string ResourceType = "CUBE"; >;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
