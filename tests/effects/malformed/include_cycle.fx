// expect: cycle_b.glsl:2: include cycle: include_cycle.fx -> cycle_a.glsl -> cycle_b.glsl -> cycle_a.glsl
#include "cycle_a.glsl"
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
