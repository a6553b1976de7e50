// expect: 4: texture Tex: texture file 'no-such-image.png' not found
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform sampler2D Tex < string ResourceName = "no-such-image.png"; >;
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
