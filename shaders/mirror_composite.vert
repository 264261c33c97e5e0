#version 300 es
// The mirror surface, looking up its colour in the reflection texture.

layout(location = 0) in vec3 a_position;

uniform mat4 u_view_projection;  // the camera, in the context's depth range
uniform mat4 u_model;            // object -> world
uniform mat4 u_reflection_matrix; // the pair the reflection texture was rendered with

out vec4 v_reflection_clip;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    // Clip coordinates, divided per fragment: a projective texture lookup.
    v_reflection_clip = u_reflection_matrix * world;
    gl_Position = u_view_projection * world;
}
