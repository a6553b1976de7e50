// expect: 8: pass p samples Buffer through Tex while rendering into it
#include "standard.glsl"
GLSLShader FS { layout(location = 0) out vec4 c; void main() { c = vec4(1.0); } }
texture Buffer : RENDERCOLORTARGET;
uniform sampler2D Tex = sampler_state { Texture = Buffer; };
GLSLShader ReadFS { layout(location = 0) out vec4 c; void main() { c = texture(Tex, vec2(0.5)); } }
technique T {
  pass p { VertexShader = StandardVS; FragmentShader = ReadFS; RenderColorTarget0 = Buffer; }
}
