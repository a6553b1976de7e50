uniform int A = 4294967296;
GLSLShader VS { void main() { gl_Position = vec4(0.0); } }
GLSLShader FS { out vec4 color; void main() { color = vec4(1.0); } }
technique T { pass P { VertexShader = VS; FragmentShader = FS; } }
