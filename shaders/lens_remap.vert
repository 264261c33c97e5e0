#version 300 es
// A full-screen triangle without vertex attributes: gl_VertexID 0, 1, 2 ->
// clip (-1, -1), (3, -1), (-1, 3).

void main() {
    gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);
}
