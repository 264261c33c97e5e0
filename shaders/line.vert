#version 300 es
// World-space lines and points of one flat colour (frustum view).

layout(location = 0) in vec3 a_position;

uniform mat4 u_view_projection; // in the context's depth range

void main() {
    gl_PointSize = 1.0;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
