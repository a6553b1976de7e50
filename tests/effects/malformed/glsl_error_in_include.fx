// expect: broken_function.glsl:3: error
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
#include "broken_function.glsl"
GLSLShader UsesFS { layout(location = 0) out vec4 c; void main() { c = vec4(helper(1.0)); } }
technique T { pass p { VertexShader = StandardVS; FragmentShader = UsesFS; } }
