// expect: 2: unterminated shader FS
GLSLShader FS {
  void main() { }
technique T { pass p { VertexShader = FS; FragmentShader = FS; } }
