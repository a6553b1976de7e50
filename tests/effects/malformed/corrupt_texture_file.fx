// expect: 4: corrupt.png: cannot read image
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform sampler2D Tex < string ResourceName = "corrupt.png"; >;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
