#version 300 es
// One triangle that covers the whole viewport, made from gl_VertexID: draw it with
// glDrawArrays(GL_TRIANGLES, 0, 3) and any vertex array bound, no vertex buffer. One triangle
// instead of two avoids shading the diagonal's pixels twice.
// v_uv runs 0..1 across the viewport with (0, 0) at the bottom left, GL's window origin.

out vec2 v_uv;

void main() {
  // Vertices 0, 1, 2 -> (0, 0), (2, 0), (0, 2): the viewport is the triangle's lower-left quarter.
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  v_uv = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
