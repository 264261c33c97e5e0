// The hot pair updates (crop §5.1, reflect and oblique clip §5.2), written
// to be inlined into the public functions of src/crop.cpp, reflect.cpp,
// oblique_clip.cpp and mirror.cpp (docs/performance.md, issue 14):
// - every result column is computed as a whole and stored once, straight
//   into the returned Result (PairFactory::keep_sign_result);
// - nothing here builds text: every refusal calls a cold, never-inlined
//   function that takes the offending values (the error path stays out of
//   the instruction stream and of the inliner's budget);
// - the sums are GLM's, in GLM's order, so crop and reflect give the same
//   bits as the out-of-line versions they replace.
#pragma once

#include "frustum/crop.hpp"
#include "frustum/detail/pair_factory.hpp"
#include "frustum/plane.hpp"

#include <cmath>
#include <limits>

#if defined(__GNUC__)
#define FRUSTUM_HOT_INLINE inline __attribute__((always_inline))
#define FRUSTUM_COLD __attribute__((cold, noinline))
#else
#define FRUSTUM_HOT_INLINE inline
#define FRUSTUM_COLD
#endif

namespace frustum::detail {

// ---- refusals (src/pair_update_errors.cpp; texts pinned by tests/math) ----

// "crop rectangle must be finite" / "... sizes must be > 0" / "... inside the image".
template <class T>
FRUSTUM_COLD Error crop_rect_error(const CropRect<T>& rect, const char* function);
// "plane must be finite" / "plane normal must be non-zero and finite".
template <class T>
FRUSTUM_COLD Error plane_error(const Vec4<T>& abcd, const char* function);

// ---- checks ----

template <class T>
FRUSTUM_HOT_INLINE bool crop_rect_is_valid(const CropRect<T>& r) {
    // Every comparison is false for NaN; infinities fail the size bounds.
    return std::isfinite(r.full_width) && std::isfinite(r.full_height) && r.full_width > T(0) &&
           r.full_height > T(0) && r.width > T(0) && r.height > T(0) && r.x >= T(0) && r.y >= T(0) &&
           r.x + r.width <= r.full_width && r.y + r.height <= r.full_height;
}

// One test catches NaN and infinity in any coefficient (inf - inf and
// anything + NaN are not finite) and a zero or overflowing normal.
template <class T>
FRUSTUM_HOT_INLINE bool plane_usable(const Vec4<T>& abcd, T normal_length_squared) {
    return std::isfinite(normal_length_squared + abcd.w) && normal_length_squared > T(0);
}

template <class T>
FRUSTUM_HOT_INLINE T normal_length_squared(const Vec4<T>& abcd) {
    const Vec3<T> n(abcd);
    return glm::dot(n, n);
}

// ---- crop (eq. 14-15) ----

// Crop coefficients (eq. 14): x' = w x + (w - 1 - 2 X/bw) w_clip.
template <class T>
struct CropMap {
    T sx, tx, sy, ty;
};
template <class T>
FRUSTUM_HOT_INLINE CropMap<T> crop_map(const CropRect<T>& r) {
    const T inv_width = T(1) / r.width, inv_height = T(1) / r.height;
    const T w = r.full_width * inv_width;
    const T h = r.full_height * inv_height;
    return {w, w - T(1) - T(2) * r.x * inv_width, h, h - T(1) - T(2) * r.y * inv_height};
}

// Row 0 of M' for the clip-space map x' = sx x + tx w, y' = sy y + ty w is
// sx m0 + tx m3 (row 1 likewise); column j of M' is therefore
// M_j * (sx, sy, 1, 1) + M_j.w * (tx, ty, 0, 0). The inverse undoes it
// column-wise: inv0 / sx, inv1 / sy, inv3 - (tx / sx) inv0 - (ty / sy) inv1.
template <class T>
FRUSTUM_HOT_INLINE Vec4<T> scale_offset_column(const Vec4<T>& column, const Vec4<T>& scale, const Vec4<T>& offset) {
    return column * scale + column.w * offset;
}

template <class T>
FRUSTUM_HOT_INLINE Result<MatrixPair<T>> scale_offset_xy(const MatrixPair<T>& pair, T sx, T tx, T sy, T ty) {
    const Mat4<T>& m = pair.matrix();
    const Mat4<T>& inv = pair.inverse();
    const Vec4<T> scale(sx, sy, T(1), T(1));
    const Vec4<T> offset(tx, ty, T(0), T(0));
    const T inv_sx = T(1) / sx, inv_sy = T(1) / sy;
    return PairFactory::keep_sign_result<T>(
        scale_offset_column(m[0], scale, offset), scale_offset_column(m[1], scale, offset),
        scale_offset_column(m[2], scale, offset), scale_offset_column(m[3], scale, offset), inv[0] * inv_sx,
        inv[1] * inv_sy, inv[2], inv[3] - (tx * inv_sx) * inv[0] - (ty * inv_sy) * inv[1], PairFactory::traits(pair));
}

// ---- reflect (eq. 16, rank-one form) ----

// M' = M R = M - 2 (M n) c^T: column j of M' is M_j - 2 c_j (M n).
// inv' = R inv = inv - 2 n (c^T inv): column j gets -2 (c . inv_j) n.
// c is the unit plane.
template <class T>
FRUSTUM_HOT_INLINE Result<MatrixPair<T>> reflect_unit(const MatrixPair<T>& pair, const Vec4<T>& c) {
    const Mat4<T>& m = pair.matrix();
    const Mat4<T>& inv = pair.inverse();
    const Vec4<T> n(c.x, c.y, c.z, T(0));
    const Vec4<T> m_n = m * n;
    return PairFactory::keep_sign_result<T>(
        m[0] - (T(2) * c[0]) * m_n, m[1] - (T(2) * c[1]) * m_n, m[2] - (T(2) * c[2]) * m_n,
        m[3] - (T(2) * c[3]) * m_n, inv[0] - (T(2) * glm::dot(c, inv[0])) * n,
        inv[1] - (T(2) * glm::dot(c, inv[1])) * n, inv[2] - (T(2) * glm::dot(c, inv[2])) * n,
        inv[3] - (T(2) * glm::dot(c, inv[3])) * n, PairFactory::flipped_traits(pair));
}

// ---- oblique clip (eq. 20-27, column form; oblique_clip.hpp) ----

// The oblique clip of the pair (m, inv) by the plane p, which need not be
// unit: every output is invariant under p's scale (k c and X are). c_clip is
// p in this pair's clip space, Q = k_inverse q and m3 . Q with m3 = k_row3
// and the sign k_sign (oblique_clip_core.hpp: mirror forms them on the
// unreflected pair). When a check fails or the numbers leave the safe range
// it returns slow(): the caller's normalized reference form (cold, in
// src/oblique_clip.cpp and mirror.cpp), which refuses with the error text
// or, at a rounding boundary of a check, gives the result.
//
// One division for k and 1 / X_2: with a = (z_f - z_n) (m3 . Q) and
// b = c . Q, k (z_f - z_n) = a / b and X_2 = (a / b) c'_z, so g = 1 / (a b c'_z)
// gives both: (z_f - z_n) k = a a c'_z g and 1 / X_2 = b b g.
template <class T, class Slow>
FRUSTUM_HOT_INLINE Result<MatrixPair<T>> clip_columns(const Mat4<T>& m, const Mat4<T>& inv, const Vec4<T>& p,
                                                      const Vec4<T>& c_clip, const Mat4<T>& k_inverse,
                                                      const Vec4<T>& k_row3, T k_sign, DepthRange depth,
                                                      unsigned traits, Slow&& slow) {
    const T z_near = clip_z_near<T>(depth);
    const T z_far = clip_z_far<T>(depth);
    const T span = z_far - z_near;
    const T eps = std::numeric_limits<T>::epsilon();
    const T floor = T(64) * eps;

    // Eye strictly on the negative side, relative to the eye column's size.
    const T eye_side = span * c_clip.z;
    const T eye_scale_squared = glm::dot(inv[2], inv[2]) * glm::dot(p, p);
    // Far corner on the plane's positive side (erratum 2), not a sliver.
    const Vec4<T> q(std::copysign(T(1), c_clip.x), std::copysign(T(1), c_clip.y), z_far, T(1));
    const T c_dot_q = glm::dot(c_clip, q);
    const T scale = std::abs(c_clip.x) + std::abs(c_clip.y) + std::abs(c_clip.z) + std::abs(c_clip.w);

    // k = (m3 . Q) / (c . Q) from one Q = M^-1 q (analytic-inverse-accuracy.md).
    const Vec4<T> big_q = k_inverse * q;
    const T a = span * (k_sign * glm::dot(k_row3, big_q));
    const T b = glm::dot(p, big_q);
    const T denominator = a * b * c_clip.z;
    if (!(eye_side > T(0) && eye_side * eye_side > floor * floor * eye_scale_squared && c_dot_q > floor * scale &&
          std::isnormal(denominator))) {
        return slow();
    }
    const T g = T(1) / denominator;
    const T span_k = a * a * c_clip.z * g;
    const T inv_x2 = b * b * g;

    // New row 2 (eq. 22 generalized): (z_f - z_n) k c + z_n m3.
    // T^-1 (eq. 26-27), X = (z_f - z_n) k c' + z_n e3: column 2 / X_2,
    // column j - (X_j / X_2) column 2.
    const Vec4<T> x = span_k * c_clip + Vec4<T>(T(0), T(0), T(0), z_near);
    return PairFactory::keep_sign_result<T>(
        Vec4<T>(m[0].x, m[0].y, span_k * p[0] + z_near * m[0].w, m[0].w),
        Vec4<T>(m[1].x, m[1].y, span_k * p[1] + z_near * m[1].w, m[1].w),
        Vec4<T>(m[2].x, m[2].y, span_k * p[2] + z_near * m[2].w, m[2].w),
        Vec4<T>(m[3].x, m[3].y, span_k * p[3] + z_near * m[3].w, m[3].w), inv[0] - (x.x * inv_x2) * inv[2],
        inv[1] - (x.y * inv_x2) * inv[2], inv[2] * inv_x2, inv[3] - (x.w * inv_x2) * inv[2], traits);
}

} // namespace frustum::detail
