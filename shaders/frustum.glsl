// frustum.glsl: the GPU twins of the frustum library's per-frame math, as
// GLSL ES 3.00 functions. No #version line: a program that needs them gets
// this text inserted right after its own "#version 300 es" line
// (render::Programs does that; tests/gl/render_glsl_twins_test.cpp checks
// every function against the C++ library).
//
// Conventions as in the library (docs/conventions.md): column
// vectors, clip = M * world; row i of M is the paper's column m_i (planes),
// column i of M^-1 is the paper's row m_i' (key points). The depth range is
// passed as the clip z of the near and far planes: (0, 1), (-1, 1) or (1, 0).

// Row i of a matrix: the paper's m_i.
vec4 frustum_row(mat4 m, int i) {
    return vec4(m[0][i], m[1][i], m[2][i], m[3][i]);
}

// section 3.1, eq. 1 with erratum 11: the six planes, inward (positive inside), in
// the order left, right, bottom, top, near, far, not normalized. With
// s = sign(z_far - z_near):
//   L = m3 + m0, R = m3 - m0, B = m3 + m1, T = m3 - m1,
//   N = s (m2 - z_near m3), F = s (z_far m3 - m2).
// An infinite far plane comes out with a (near) zero normal.
void frustum_raw_planes(mat4 m, float z_near, float z_far, out vec4 planes[6]) {
    vec4 m0 = frustum_row(m, 0), m1 = frustum_row(m, 1), m2 = frustum_row(m, 2), m3 = frustum_row(m, 3);
    float s = z_far > z_near ? 1.0 : -1.0;
    planes[0] = m3 + m0;
    planes[1] = m3 - m0;
    planes[2] = m3 + m1;
    planes[3] = m3 - m1;
    planes[4] = s * (m2 - z_near * m3);
    planes[5] = s * (z_far * m3 - m2);
}

// |normal| = 1, so plane . (p, 1) is a signed distance; a zero normal (no
// plane, e.g. an infinite far plane) is returned unchanged.
vec4 frustum_normalized_plane(vec4 plane) {
    float length_xyz = length(plane.xyz);
    return length_xyz > 0.0 ? plane / length_xyz : plane;
}

// frustum_raw_planes(), each normalized.
void frustum_planes(mat4 m, float z_near, float z_far, out vec4 planes[6]) {
    frustum_raw_planes(m, z_near, z_far, planes);
    for (int i = 0; i < 6; ++i) {
        planes[i] = frustum_normalized_plane(planes[i]);
    }
}

// section 3.2, eq. 8: corner i (0..7 = C1..C8, near corners first) as a homogeneous
// point, x m0' + y m1' + z m2' + m3' with the clip corner (x, y, z) taken in
// the paper's order (1, 1), (-1, 1), (-1, -1), (1, -1).
vec4 frustum_corner(mat4 inverse_m, int i, float z_near, float z_far) {
    int k = i - 4 * (i / 4);
    float x = (k == 0 || k == 3) ? 1.0 : -1.0;
    float y = k < 2 ? 1.0 : -1.0;
    float z = i < 4 ? z_near : z_far;
    return x * inverse_m[0] + y * inverse_m[1] + z * inverse_m[2] + inverse_m[3];
}

// section 3.2, eq. 8: the centre D = z_mid m2' + m3' (z_mid = 0.5 in the paper's range).
vec4 frustum_center(mat4 inverse_m, float z_near, float z_far) {
    return 0.5 * (z_near + z_far) * inverse_m[2] + inverse_m[3];
}

// section 3.2, eq. 7 (erratum 15): the eye O = k m2', with the sign of k that puts
// it on the near plane's negative side (w > 0 for a finite eye; an
// orthographic eye at infinity points back, away from the frustum).
vec4 frustum_eye(mat4 m, mat4 inverse_m, float z_near, float z_far) {
    float s = z_far > z_near ? 1.0 : -1.0;
    vec4 near_plane = s * (frustum_row(m, 2) - z_near * frustum_row(m, 3));
    return dot(near_plane, inverse_m[2]) > 0.0 ? -inverse_m[2] : inverse_m[2];
}

// section 5.1, eq. 14-15 (erratum 1: the offset is from the bottom-left): the crop
// to rect = (x, y, width, height) of a full image of size full = (W, H), in
// any one unit. With w = W / width, h = H / height:
//   x' = w x + (w - 1 - 2 x / width) w_clip,   y' likewise,
// i.e. rows 0 and 1 of M pick up row 3:
//   m0' = w m0 + tx m3,  m1' = h m1 + ty m3.
vec4 frustum_crop_coefficients(vec4 rect, vec2 full) {
    vec2 scale = full / rect.zw;
    vec2 offset = scale - 1.0 - 2.0 * rect.xy / rect.zw;
    return vec4(scale.x, offset.x, scale.y, offset.y);
}

mat4 frustum_crop_matrix(mat4 m, vec4 rect, vec2 full) {
    vec4 c = frustum_crop_coefficients(rect, full);
    mat4 cropped = m;
    for (int j = 0; j < 4; ++j) {
        cropped[j][0] = c.x * m[j][0] + c.y * m[j][3];
        cropped[j][1] = c.z * m[j][1] + c.w * m[j][3];
    }
    return cropped;
}

// The matching inverse (eq. 15, sparse): only columns 0, 1 and 3 change,
//   inv0' = inv0 / w,  inv1' = inv1 / h,  inv3' = inv3 - (tx / w) inv0 - (ty / h) inv1.
mat4 frustum_crop_inverse(mat4 inverse_m, vec4 rect, vec2 full) {
    vec4 c = frustum_crop_coefficients(rect, full);
    mat4 cropped = inverse_m;
    cropped[0] = inverse_m[0] / c.x;
    cropped[1] = inverse_m[1] / c.z;
    cropped[3] = inverse_m[3] - (c.y / c.x) * inverse_m[0] - (c.w / c.z) * inverse_m[1];
    return cropped;
}

// section 6: a frustum of six unit planes with OUTWARD normals, order left, right,
// bottom, top, near, far (d_i < 0 inside). The denominators of eq. 36,
// (d_l + d_r, d_t + d_b, d_n + d_f): negative inside, zero on the
// degenerate set where eq. 36 blows up (docs/non-affine.md).
vec3 frustum_non_affine_denominators(vec4 planes[6], vec3 p) {
    vec4 q = vec4(p, 1.0);
    return vec3(dot(planes[0], q) + dot(planes[1], q), dot(planes[3], q) + dot(planes[2], q),
                dot(planes[4], q) + dot(planes[5], q));
}

// eq. 36: u = d_l / (d_l + d_r), v = d_t / (d_t + d_b), s = d_n / (d_n + d_f),
// mapped to clip space as x = 2u - 1 (left -1), y = 1 - 2v (top +1),
// z = z_near + s (z_far - z_near), w = 1. The caller keeps p away from the
// degenerate set (every denominator < 0).
vec4 frustum_non_affine_clip(vec4 planes[6], vec3 p, float z_near, float z_far) {
    vec4 q = vec4(p, 1.0);
    vec3 d = frustum_non_affine_denominators(planes, p);
    vec3 uvs = vec3(dot(planes[0], q), dot(planes[3], q), dot(planes[4], q)) / d;
    return vec4(2.0 * uvs.x - 1.0, 1.0 - 2.0 * uvs.y, z_near + uvs.z * (z_far - z_near), 1.0);
}

// Depth that decodes: the world point a depth-buffer texel stores, for any
// pair and depth range. `depth` is the window depth the buffer holds, in
// [0, 1] with glDepthRangef(0, 1); the clip z/w that produced it is
// z_lo + depth (z_hi - z_lo) with z_lo, z_hi the smaller and larger of
// (z_near, z_far): 2 depth - 1 for the [-1, 1] range (GL's default clip
// control), depth itself for [0, 1] and reversed [1, 0] (GL_ZERO_TO_ONE).
float frustum_clip_z_from_depth(float depth, float z_near, float z_far) {
    float z_lo = min(z_near, z_far);
    return z_lo + depth * (max(z_near, z_far) - z_lo);
}

// section 3.2 (the inverse takes clip points back to world): world =
// M^-1 (x_ndc, y_ndc, z_clip, 1), divided by its w. `inverse_m` must be the
// inverse of the matrix that wrote the depth, in the range it was written
// with: for an oblique near plane that is the oblique pair's inverse, not
// the inverse of the projection before the plane was swapped in.
vec3 frustum_world_from_depth(mat4 inverse_m, vec2 ndc_xy, float depth, float z_near, float z_far) {
    vec4 p = inverse_m * vec4(ndc_xy, frustum_clip_z_from_depth(depth, z_near, z_far), 1.0);
    return p.xyz / p.w;
}
