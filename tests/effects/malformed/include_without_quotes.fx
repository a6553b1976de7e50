// expect: 2: #include needs a file name in quotes
#include standard.glsl
technique T { pass p { VertexShader = StandardVS; FragmentShader = FS; } }
