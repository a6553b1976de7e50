// expect: 4: texture Lonely needs a ResourceName annotation
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
texture Lonely < string Format = "8"; >;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
