#version 450
// Deferred composite pass (SPEC 3.7): one full-screen triangle from the
// vertex index, no vertex buffer (draw 3 vertices; OpenGL needs a bound VAO).
// Clip (-1,-1), (3,-1), (-1,3) covers the whole of [-1, 1]^2.
void main() {
  vec2 corner = vec2(float((gl_VertexIndex & 1) * 4 - 1), float((gl_VertexIndex & 2) * 2 - 1));
  gl_Position = vec4(corner, 0.5, 1.0);
}
