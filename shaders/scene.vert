#version 300 es
// Lit scene geometry. Attribute locations match render::AttributeLocation.

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;    // COLOR_0, linear; constant white when absent
layout(location = 3) in vec2 a_texcoord; // TEXCOORD_0; constant (0, 0) when absent

uniform mat4 u_view_projection; // MatrixPair::matrix() in the context's depth range
uniform mat4 u_model;           // object -> world
uniform mat3 u_normal_matrix;   // cofactor of u_model's 3x3 (inverse transpose up to scale)
uniform float u_point_size_px;  // used by GL_POINTS only

out vec3 v_world;
out vec3 v_normal;
out vec4 v_color;
out vec2 v_texcoord;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
    v_color = a_color;
    v_texcoord = a_texcoord;
    gl_PointSize = u_point_size_px;
    gl_Position = u_view_projection * world;
}
