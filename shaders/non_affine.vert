#version 300 es
// Scene geometry through a non-affine frustum (paper section 6, eq. 36),
// lit by scene.frag. frustum.glsl is inserted after the #version line. The
// vertices are already in world space (plan::WorldGeometry), and the
// CPU has dropped every triangle with a vertex whose denominators are not
// safely negative (docs/non-affine.md).

layout(location = 0) in vec3 a_position; // world
layout(location = 1) in vec3 a_normal;   // world
layout(location = 2) in vec4 a_color;    // material base colour x COLOR_0, linear
layout(location = 3) in vec2 a_texcoord;

uniform vec4 u_planes[6]; // unit, OUTWARD: left, right, bottom, top, near, far
uniform float u_z_near;   // clip z of the near (s = 0) and far (s = 1) planes
uniform float u_z_far;
uniform vec4 u_crop;      // ndc.xy * u_crop.xy + u_crop.zw: a poster tile's crop (eq. 14); (1, 1, 0, 0): the frame

out vec3 v_world;
out vec3 v_normal;
out vec4 v_color;
out vec2 v_texcoord;

void main() {
    v_world = a_position;
    v_normal = a_normal;
    v_color = a_color;
    v_texcoord = a_texcoord;
    // eq. 36 gives the normalized device coordinates. They are handed on with
    // w = -(d_l + d_r + d_t + d_b) / 2 (> 0 for every drawn vertex): the
    // position is the same, but varyings are interpolated with 1 / w, which
    // is exact perspective-correct interpolation when the six planes come
    // from a projection matrix (then both denominators are proportional to
    // the eye depth).
    vec3 d = frustum_non_affine_denominators(u_planes, a_position);
    float w = -0.5 * (d.x + d.y);
    vec3 ndc = frustum_non_affine_clip(u_planes, a_position, u_z_near, u_z_far).xyz;
    gl_Position = vec4(vec3(ndc.xy * u_crop.xy + u_crop.zw, ndc.z) * w, w);
}
