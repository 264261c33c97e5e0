// One lens tile's pair (paper §5.4) assembled from what its grid shares:
// the tile's four warped corners X_0..X_3 (bottom-left, bottom-right,
// top-right, top-left; relative to the eye, which is the origin), their
// in-plane coordinates (u, v) on the refraction plane, and its four edges
// as 3D vectors (bottom X_1 - X_0, top X_2 - X_3, left X_3 - X_0, right
// X_2 - X_1; each shared with the neighbouring tile). Internal to
// lens_tiles(); docs/performance.md "Lens tiles from points".
//
// The inverse from points (§3.2: the inverse's columns are key points).
// M^-1 (s_x, s_y, z_n, 1) = mu_i (X_i, 1) for the corner i at NDC
// (s_x, s_y), and M^-1 (0, 0, 1, 0) = (0, 0, 0, lambda) (the eye). The four
// corners of a plane quad are linearly dependent,
//   mu_0 X_0 + mu_2 X_2 = mu_1 X_1 + mu_3 X_3,
//   mu_i = det of the other three corners (mu_0 = det(X_1, X_2, X_3), ...),
// and a det of three points of the refraction plane is their in-plane
// doubled area A_i times one constant, so mu_i ~ A_i. Summing the corner
// equations with the signs of s_x, s_y and 1 (P_i = mu_i (X_i, 1)):
//   c0 = (P_1 - P_0 + P_2 - P_3) / 4,  c1 = (P_3 - P_0 + P_2 - P_1) / 4,
//   c3 = (P_0 + P_1 + P_2 + P_3) / 4 - z_n c2,  c2 = (0, 0, 0, lambda).
// c0 and c1 are a tile's width where the P_i are the eye's distance, so
// they are formed from the edges, without that cancellation:
//   P_1 - P_0 = mu_1 (X_1 - X_0) + (mu_1 - mu_0) (X_0, 1), and
//   mu_1 - mu_0 = mu_2 - mu_3 ~ A_1 - A_0 = cross(X_1 - X_0, X_3 - X_2)
// in the plane (A_0 + A_2 = A_1 + A_3: the quad's area split along either
// diagonal); likewise mu_3 - mu_0 = mu_2 - mu_1 ~ cross(X_1 - X_2, X_3 - X_0).
//
// The matrix from planes through the key points (§3.1): row i of M is the
// plane through the three columns of M^-1 other than column i, which for
// the rows with w = 0 (m0, m1, m3 contain the eye c2) is a cross product,
//   m0 = (c1 x c3) / d_0, m1 = (c3 x c0) / d_1, m3 = (c0 x c1) / d_3,
//   d_i the row's own triple product with c_i (each det(c0, c1, c3) of the
//   xyz parts in exact arithmetic; apart, each m_i . c_i is 1 to rounding),
// and m2 = z_n m3 + beta N (eq. 11, N the refraction plane, unit; the
// plane through c0, c1, c3 with m2 . c2 = 1). With z_n = 0 that is beta N
// alone; otherwise the sum cancels and m2 is formed from the columns' w
// (lens_tile_rows). So M and
// M^-1 agree to rounding (the residual |M M^-1 - I| of §4's plane
// intersections, at a fraction of their cost). The far plane (§4.1, eq. 12
// with the tile's four far points r X_i, r = far / near distance): the
// nearest that keeps every corner ray inside up to r, reached by the corner
// of largest mu. Scaling mu so that the largest is 1 / d_n (d_n the near
// distance) makes beta = (z_f - z_n) r / (r - 1) and lambda = 1 / (beta
// N_w) = -1 / (beta d_n) constants of the grid. The same far plane
// from_planes(sides, far_points) gives (both contain the line m3 = N = 0).
//
// The tile is then moved from eye-relative to world coordinates:
// M T(-eye) (column 3 minus M's first three columns times the eye) and
// T(eye) M^-1 (xyz of each column plus the eye times its w).
#pragma once

#include "frustum/detail/simd4.hpp"
#include "frustum/types.hpp"

#include <algorithm>

#if defined(__GNUC__)
#define FRUSTUM_LENS_INLINE __attribute__((always_inline))
#else
#define FRUSTUM_LENS_INLINE
#endif

namespace frustum::detail {

// What every tile of one grid shares.
template <class T>
struct LensTileShared {
    V4<T> far_row;    // beta N, eye-relative (eq. 11-12)
    V4<T> eye;        // (eye, 0), world
    T z_near = 0;     // z_n of the depth range
    T lambda = 0;     // M^-1 e_z = (0, 0, 0, lambda), eye-relative
    T inv_near_m = 0; // 1 / d_n
    T orientation = 0; // d_n / (center . (x_axis x y_axis)): det(X_a, X_b, X_c) = A d_n / orientation
};

// Where a tile's shared parts are: its corners (X, 1) (eye-relative), their
// in-plane coordinates (u, v, 0, 0) and its edges (w = 0), in the grid's
// scratch arrays (read in place, not copied per tile).
template <class T>
struct LensTileInput {
    const Vec4<T>* corners[4]; // X_0..X_3
    const Vec4<T>* plane[4];   // (u_i, v_i, 0, 0)
    const Vec4<T>* bottom;     // X_1 - X_0
    const Vec4<T>* top;        // X_2 - X_3
    const Vec4<T>* left;       // X_3 - X_0
    const Vec4<T>* right;      // X_2 - X_1
    // For lens_tile_rows_from_planes only: the edges' planes through the eye,
    // X_0 x X_3, X_1 x X_2, X_0 x X_1, X_3 x X_2 (left, right, bottom, top).
    const Vec4<T>* normals[4];
};

template <class T>
FRUSTUM_LENS_INLINE inline V4<T> cross3(const V4<T>& a, const V4<T>& b) { // xyz parts; w = a_w b_w - a_w b_w = 0
    if constexpr (std::is_same_v<T, float>) {
        const V4<T> a_yzx = __builtin_shufflevector(a, a, 1, 2, 0, 3);
        const V4<T> b_yzx = __builtin_shufflevector(b, b, 1, 2, 0, 3);
        const V4<T> c = a * b_yzx - a_yzx * b; // (a x b) in the order z, x, y
        return __builtin_shufflevector(c, c, 1, 2, 0, 3);
    } else {
        return V4<T>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0], T(0)};
    }
}

template <class T>
FRUSTUM_LENS_INLINE inline V4<T> times(const V4<T>& v, T s) {
    return v * s;
}

// The tile's inverse (eye-relative) into c[4]. False for a tile whose
// corners are not a strictly convex quad of one orientation (doubled areas
// of one sign, none below 1e-6 of the largest; NaN fails too).
template <class T>
FRUSTUM_LENS_INLINE inline bool lens_tile_inverse(const LensTileInput<T>& in, const LensTileShared<T>& shared, V4<T>* c) {
    const T u[4] = {in.plane[0]->x, in.plane[1]->x, in.plane[2]->x, in.plane[3]->x};
    const T v[4] = {in.plane[0]->y, in.plane[1]->y, in.plane[2]->y, in.plane[3]->y};
    const T b_u = u[1] - u[0], b_v = v[1] - v[0]; // bottom edge
    const T l_u = u[3] - u[0], l_v = v[3] - v[0]; // left edge
    const T d_u = u[2] - u[0], d_v = v[2] - v[0]; // diagonal 0 -> 2
    const T r_u = u[2] - u[1], r_v = v[2] - v[1]; // right edge
    const T t_u = u[2] - u[3], t_v = v[2] - v[3]; // top edge
    const T e_u = u[3] - u[1], e_v = v[3] - v[1]; // diagonal 1 -> 3
    const T a0 = r_u * e_v - r_v * e_u; // ~ det(X_1, X_2, X_3)
    const T a1 = d_u * l_v - d_v * l_u; // ~ det(X_0, X_2, X_3)
    const T a2 = b_u * l_v - b_v * l_u; // ~ det(X_0, X_1, X_3)
    const T a3 = b_u * d_v - b_v * d_u; // ~ det(X_0, X_1, X_2)
    const T hi = std::max(std::max(a0, a1), std::max(a2, a3));
    const T lo = std::min(std::min(a0, a1), std::min(a2, a3));
    const T ref = hi > T(0) ? hi : lo; // the largest |A_i|, of the quad's orientation
    const T tolerance = T(1e-6) * ref;
    if (!(hi > T(0) ? lo > tolerance : hi < tolerance)) {
        return false;
    }
    const T scale = shared.inv_near_m / ref;   // mu_i = A_i scale: the largest 1 / d_n
    const T across = (b_v * t_u - b_u * t_v) * scale; // mu_1 - mu_0 = mu_2 - mu_3: cross(bottom, -top)
    const T up = (l_u * r_v - l_v * r_u) * scale;     // mu_3 - mu_0 = mu_2 - mu_1: cross(left, right)
    const T mu[4] = {a0 * scale, a1 * scale, a2 * scale, a3 * scale};
    const V4<T> x[4] = {load(*in.corners[0]), load(*in.corners[1]), load(*in.corners[2]), load(*in.corners[3])};
    const V4<T> quarter = splat(T(0.25));
    c[0] = ((times<T>(load(*in.bottom), mu[1]) + times<T>(load(*in.top), mu[2])) + times<T>(x[0] + x[3], across)) *
           quarter;
    c[1] = ((times<T>(load(*in.left), mu[3]) + times<T>(load(*in.right), mu[2])) + times<T>(x[0] + x[1], up)) *
           quarter;
    c[2] = V4<T>{T(0), T(0), T(0), shared.lambda};
    c[3] = ((times<T>(x[0], mu[0]) + times<T>(x[1], mu[1])) + (times<T>(x[2], mu[2]) + times<T>(x[3], mu[3]))) * quarter -
           V4<T>{T(0), T(0), T(0), shared.z_near * shared.lambda};
    return true;
}

// The tile's rows (eye-relative) from its inverse's columns. False when the
// columns do not span space.
template <class T>
FRUSTUM_LENS_INLINE inline bool lens_tile_rows(const V4<T>* c, const LensTileShared<T>& shared, Cols<T>& rows) {
    const V4<T>& c0 = c[0];
    const V4<T>& c1 = c[1];
    const V4<T>& c3 = c[3];
    const V4<T> k0 = cross3<T>(c1, c3), k1 = cross3<T>(c3, c0), k3 = cross3<T>(c0, c1); // w = 0
    // Each row scaled by its own triple product, k_i . c_i (all three are
    // det(c0, c1, c3) in exact arithmetic), so that m_i . c_i = 1 to one
    // rounding: one shared det left the diagonal of M M^-1 off by the
    // three products' rounding differences, the largest entry of the
    // residual in a third of the tiles. The three sums side by side.
    const Cols<T> products = transpose(Cols<T>{{k0 * c0, k1 * c1, k3 * c3, splat<T>(T(0))}});
    const V4<T> diagonal = (products.c[0] + products.c[1]) + products.c[2] + V4<T>{T(0), T(0), T(0), T(1)};
    const T det = diagonal[2];
    if (!(std::abs(det) > T(0)) || !std::isfinite(det)) {
        return false;
    }
    const V4<T> inv = splat<T>(T(1)) / diagonal;
    rows.c[0] = times<T>(k0, inv[0]);
    rows.c[1] = times<T>(k1, inv[1]);
    rows.c[3] = times<T>(k3, inv[2]);
    if (shared.z_near == T(0)) {
        rows.c[2] = shared.far_row; // eq. 11 with z_n = 0: m2 = beta N
    } else {
        // Where z_n != 0, z_n m3 + beta N nearly cancels (reversed: m2 =
        // m3 - |beta| N), and the rounding of m3 and N, large against m2
        // itself, made |M M^-1 - I| 1.2-5x the exact inverse's. The same row
        // from its definition instead: m2 . c_j = 0 for j = 0, 1, 3 and
        // m2 . c2 = m2_w lambda = 1, so with m2_w = beta N_w = 1 / lambda
        // and m0, m1, m3 the dual basis of c0, c1, c3 (w = 0),
        //   m2 = (-m2_w (c0_w m0 + c1_w m1 + c3_w m3), m2_w)
        // (docs/performance.md "Lens tiles from points").
        const T m2_w = shared.far_row[3];
        const V4<T> xyz = (times<T>(rows.c[0], c0[3]) + times<T>(rows.c[1], c1[3])) + times<T>(rows.c[3], c3[3]);
        rows.c[2] = times<T>(xyz, -m2_w) + V4<T>{T(0), T(0), T(0), m2_w};
    }
    return true;
}

// The same rows from the edge planes alone (§4, eq. 10 up to each plane's
// scale; the forward construction a re-inverting baseline starts from):
// m3 + m0 = a_L L, m3 - m0 = a_R R, m3 + m1 = a_B B, m3 - m1 = a_T T, with
// each a fixed by a corner off its plane (x + w = 2 at bottom-right for L):
// a_L = 2 / (mu_1 mu_2), a_R = 2 / (mu_0 mu_3), a_B = 2 / (mu_2 mu_3),
// a_T = 2 / (mu_0 mu_1) (det units: L . X_1 = det(X_3, X_0, X_1) = mu_2), so
// m0 = (a_L L - a_R R) / 2, m1 = (a_B B - a_T T) / 2, m3 = (a_L L + a_R R +
// a_B B + a_T T) / 4 and m2 = z_n m3 + beta N. L = -normals[0], T =
// -normals[3]. False for a degenerate tile, as lens_tile_inverse.
template <class T>
FRUSTUM_LENS_INLINE inline bool lens_tile_rows_from_planes(const LensTileInput<T>& in, const LensTileShared<T>& shared, Cols<T>& rows) {
    const T u[4] = {in.plane[0]->x, in.plane[1]->x, in.plane[2]->x, in.plane[3]->x};
    const T v[4] = {in.plane[0]->y, in.plane[1]->y, in.plane[2]->y, in.plane[3]->y};
    const T b_u = u[1] - u[0], b_v = v[1] - v[0], l_u = u[3] - u[0], l_v = v[3] - v[0];
    const T d_u = u[2] - u[0], d_v = v[2] - v[0], r_u = u[2] - u[1], r_v = v[2] - v[1];
    const T e_u = u[3] - u[1], e_v = v[3] - v[1];
    const T a[4] = {r_u * e_v - r_v * e_u, d_u * l_v - d_v * l_u, b_u * l_v - b_v * l_u, b_u * d_v - b_v * d_u};
    const T hi = std::max(std::max(a[0], a[1]), std::max(a[2], a[3]));
    const T lo = std::min(std::min(a[0], a[1]), std::min(a[2], a[3]));
    const T ref = hi > T(0) ? hi : lo;
    const T tolerance = T(1e-6) * ref;
    if (!(hi > T(0) ? lo > tolerance : hi < tolerance)) {
        return false;
    }
    // a / 2 = A_ref orientation / (A_i A_j), with the signs of L and T.
    const T numerator = ref * shared.orientation;
    const V4<T> factors =
        V4<T>{-numerator, numerator, numerator, -numerator} /
        (V4<T>{a[1], a[0], a[2], a[0]} * V4<T>{a[2], a[3], a[3], a[1]});
    const V4<T> l = times<T>(load(*in.normals[0]), factors[0]), r = times<T>(load(*in.normals[1]), factors[1]);
    const V4<T> b = times<T>(load(*in.normals[2]), factors[2]), t = times<T>(load(*in.normals[3]), factors[3]);
    rows.c[0] = l - r;
    rows.c[1] = b - t;
    rows.c[3] = ((l + r) + (b + t)) * T(0.5);
    rows.c[2] = times<T>(rows.c[3], shared.z_near) + shared.far_row;
    const V4<T> zero = factors - factors;
    for (int i = 0; i < 4; ++i) {
        if (!(zero[i] == T(0))) {
            return false;
        }
    }
    return true;
}

// M T(-eye) from the eye-relative rows, into `matrix` (column-major).
template <class T>
FRUSTUM_LENS_INLINE inline void lens_tile_store_matrix(const Cols<T>& rows, const LensTileShared<T>& shared, Mat4<T>& matrix) {
    Cols<T> m = transpose(rows);
    const V4<T>& e = shared.eye;
    if constexpr (std::is_same_v<T, float>) {
        m.c[3] = m.c[3] - ((m.c[0] * lane<0>(e) + m.c[1] * lane<1>(e)) + m.c[2] * lane<2>(e));
    } else {
        m.c[3] = m.c[3] - ((m.c[0] * e[0] + m.c[1] * e[1]) + m.c[2] * e[2]);
    }
    for (int j = 0; j < 4; ++j) {
        std::memcpy(&matrix[j], &m.c[j], sizeof m.c[j]);
    }
}

// T(eye) M^-1 from the eye-relative columns, into `inverse`.
template <class T>
FRUSTUM_LENS_INLINE inline void lens_tile_store_inverse(const V4<T>* c, const LensTileShared<T>& shared, Mat4<T>& inverse) {
    for (int j = 0; j < 4; ++j) {
        V4<T> world;
        if constexpr (std::is_same_v<T, float>) {
            world = c[j] + shared.eye * lane<3>(c[j]);
        } else {
            world = c[j] + shared.eye * c[j][3];
        }
        std::memcpy(&inverse[j], &world, sizeof world);
    }
}

} // namespace frustum::detail
