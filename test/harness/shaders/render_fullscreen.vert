#version 450
// Full-screen pass without a vertex buffer: one triangle from gl_VertexIndex, depth 0.5.
void main() {
  vec2 p = vec2(gl_VertexIndex == 1 ? 3.0 : -1.0, gl_VertexIndex == 2 ? 3.0 : -1.0);
  gl_Position = vec4(p, 0.5, 1.0);
}
