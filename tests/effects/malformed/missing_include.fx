// expect: 2: included file 'nowhere.glsl' not found
#include "nowhere.glsl"
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
