// expect: 6: plugin 'Fit' defined twice
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
plugin Fit < string Type = "brdf-fit"; >;
plugin Fit < string Type = "brdf-fit"; >;
