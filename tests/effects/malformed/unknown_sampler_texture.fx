// expect: 4: unknown texture 'Missing'
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform sampler2D Tex = sampler_state { Texture = <Missing>; };
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
