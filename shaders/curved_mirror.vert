#version 300 es
// The curved mirror's cap (paper §4.3), drawn one patch at a time: the
// vertices are world positions on the cap, and each fragment projects its
// own position with the patch frustum's matrix (a projective lookup of the
// surface point, as for the planar mirror).

layout(location = 0) in vec3 a_position; // world space

uniform mat4 u_view_projection; // the camera, in the context's depth range
uniform mat4 u_patch_matrix;    // the patch frustum its view was rendered with

out vec4 v_patch_clip;

void main() {
    vec4 world = vec4(a_position, 1.0);
    // Clip coordinates, divided per fragment. Only x, y and w are used, and
    // they do not depend on the depth range.
    v_patch_clip = u_patch_matrix * world;
    gl_Position = u_view_projection * world;
}
