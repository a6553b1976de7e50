// expect: 4: unknown texture Format '24bit'
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform sampler2D Tex < string ResourceName = "x.png"; string Format = "24bit"; >;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
