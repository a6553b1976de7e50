// expect: 4: unknown wrap mode 'sideways'
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
uniform sampler2D Tex = sampler_state { WrapS = sideways; };
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
