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
#include "frustum/detail/simd4.hpp"
#include "frustum/plane.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

// FRUSTUM_COLD marks a fast form's reference form too (mirror_reference,
// clip_oblique_reference): the normalized computation, only reached when
// a check of the fast form fails, which gives the refusal and its text, or
// the result at a check's rounding boundary.
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

// Three four-wide comparisons, one branch: every comparison is false for
// NaN; an infinite size fails the <= max lane (and an infinite crop size
// would fail x + width <= full_width anyway), so this is exactly
// "finite, sizes > 0, inside the image".
template <class T>
FRUSTUM_HOT_INLINE bool crop_rect_is_valid(const CropRect<T>& r) {
    const V4<T> zero = splat(T(0));
    const V4<T> sizes{r.full_width, r.full_height, r.width, r.height};
    const V4<T> low{T(0), T(0), r.x + r.width, r.y + r.height};
    const V4<T> high{r.x, r.y, r.full_width, r.full_height};
    const auto ok = (sizes > zero) & (sizes <= splat(std::numeric_limits<T>::max())) & (low <= high);
    return all_lanes(ok);
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
FRUSTUM_HOT_INLINE Result<MatrixPair<T>> scale_offset_xy(const MatrixPair<T>& pair, T sx, T tx, T sy, T ty) {
    const Cols<T> m = load(pair.matrix());
    const Cols<T> inv = load(pair.inverse());
    const V4<T> scale{sx, sy, T(1), T(1)};
    const V4<T> offset{tx, ty, T(0), T(0)};
    const T inv_sx = T(1) / sx, inv_sy = T(1) / sy;
    const auto column = [&](int j) { return store<T>(m.c[j] * scale + lane<3>(m.c[j]) * offset); };
    return PairFactory::keep_sign_result<T>(column(0), column(1), column(2), column(3), store<T>(inv.c[0] * inv_sx),
                                            store<T>(inv.c[1] * inv_sy), store<T>(inv.c[2]),
                                            store<T>(inv.c[3] - (tx * inv_sx) * inv.c[0] - (ty * inv_sy) * inv.c[1]),
                                            PairFactory::traits(pair));
}

// crop(): crop_map and scale_offset_xy with x and y side by side in the
// lanes of one vector (the same IEEE operations per lane, so the same
// bits): two vector divisions where the scalar form has four.
template <class T>
FRUSTUM_HOT_INLINE Result<MatrixPair<T>> crop_pair(const MatrixPair<T>& pair, const CropRect<T>& r) {
    const Cols<T> m = load(pair.matrix());
    const Cols<T> inv = load(pair.inverse());
    const V4<T> one = splat(T(1));
    const V4<T> inv_size = one / V4<T>{r.width, r.height, T(1), T(1)};
    const V4<T> scale = V4<T>{r.full_width, r.full_height, T(1), T(1)} * inv_size; // (sx, sy, 1, 1)
    // (tx, ty, +0, +0): w - 1 - 2 X / bw as crop_map forms it.
    const V4<T> offset = (scale - one) - (T(2) * V4<T>{r.x, r.y, T(0), T(0)}) * inv_size;
    const V4<T> inv_scale = one / scale;
    const V4<T> shift = offset * inv_scale; // (tx / sx, ty / sy, ...)
    const auto column = [&](int j) { return store<T>(m.c[j] * scale + lane<3>(m.c[j]) * offset); };
    return PairFactory::keep_sign_result<T>(column(0), column(1), column(2), column(3),
                                            store<T>(inv.c[0] * lane<0>(inv_scale)),
                                            store<T>(inv.c[1] * lane<1>(inv_scale)), store<T>(inv.c[2]),
                                            store<T>(inv.c[3] - lane<0>(shift) * inv.c[0] - lane<1>(shift) * inv.c[1]),
                                            PairFactory::traits(pair));
}

// ---- reflect (eq. 16, rank-one form) ----

// M' = M R = M - 2 (M n) c^T: column j of M' is M_j - 2 c_j (M n).
// inv' = R inv = inv - 2 n (c^T inv): column j gets -2 (c . inv_j) n.
// c is the unit plane.
template <class T>
FRUSTUM_HOT_INLINE Result<MatrixPair<T>> reflect_unit(const MatrixPair<T>& pair, const Vec4<T>& unit_plane) {
    const Cols<T> m = load(pair.matrix());
    const Cols<T> inv = load(pair.inverse());
    const V4<T> c = load(unit_plane);
    const V4<T> n{c[0], c[1], c[2], T(0)};
    const V4<T> m_n = mat_vec(m, n);
    const V4<T> two_c = T(2) * c;
    const V4<T> two_c_inv = T(2) * dots(transpose(inv), c); // 2 (c . inv_j)
    return PairFactory::keep_sign_result<T>(
        store<T>(m.c[0] - two_c[0] * m_n), store<T>(m.c[1] - two_c[1] * m_n), store<T>(m.c[2] - two_c[2] * m_n),
        store<T>(m.c[3] - two_c[3] * m_n), store<T>(inv.c[0] - two_c_inv[0] * n), store<T>(inv.c[1] - two_c_inv[1] * n),
        store<T>(inv.c[2] - two_c_inv[2] * n), store<T>(inv.c[3] - two_c_inv[3] * n), PairFactory::flipped_traits(pair));
}

// ---- oblique clip (eq. 20-27, column form; oblique_clip.hpp) ----

// z_near, z_far and z_far - z_near of a depth range, by table (no branch).
template <class T>
struct alignas(16) ClipDepth { // (16 or 32 bytes: the table index is one shift)
    T z_near, z_far, span;
};
template <class T>
FRUSTUM_HOT_INLINE ClipDepth<T> clip_depth(DepthRange depth) {
    static constexpr ClipDepth<T> table[] = {
        {clip_z_near<T>(DepthRange::ZeroToOne), clip_z_far<T>(DepthRange::ZeroToOne),
         clip_z_span<T>(DepthRange::ZeroToOne)},
        {clip_z_near<T>(DepthRange::MinusOneToOne), clip_z_far<T>(DepthRange::MinusOneToOne),
         clip_z_span<T>(DepthRange::MinusOneToOne)},
        {clip_z_near<T>(DepthRange::ReversedZeroToOne), clip_z_far<T>(DepthRange::ReversedZeroToOne),
         clip_z_span<T>(DepthRange::ReversedZeroToOne)}};
    return table[static_cast<int>(depth)];
}

// The clip plane in clip space and what k needs. With M^-1 and row 3 m3 of
// the pair k is taken from (the pair itself for a plain clip, the
// unreflected pair for a mirror, see oblique_clip_core.hpp):
//   d_j = p . M^-1_j,   c' = k_sign d (rounded to T),
// k_sign = -1 for a mirror (c' = -(M^-T c) there). Two ways to k's dot
// products c . Q and m3 . Q for Q = M^-1 q:
// - In double (W = double: float pairs on x86-64 and wasm, and double
//   pairs): d and e_j = m3 . M^-1_j in double, then c . Q = d . q and
//   m3 . Q = e . q. For float pairs every product of two floats is exact
//   there, so k is rounded about once.
// - Same Q, in float (W = float: float pairs on aarch64): Q = M^-1 q, then
//   both dot products from that one Q (eq. 20-21): their common rounding
//   cancels in the quotient. (d . q and e . q in float round e apart from
//   Q; measured on aarch64 that raised clip's mean error by 50-80%, above
//   re-inverting: docs/analytic-inverse-accuracy.md.)
template <class T>
struct ClipPlane {
    V4<typename Wider<T>::type> d, e; // e: M^-T m3 (in double), or m3 itself (same Q)
    V4<T> c_clip;
};
template <bool Mirror, class T>
FRUSTUM_HOT_INLINE ClipPlane<T> clip_plane(const Cols<T>& k_inverse, const V4<T>& k_row3, const V4<T>& p) {
    using W = typename Wider<T>::type;
    ClipPlane<T> out;
    if constexpr (std::is_same_v<W, double>) {
        column_dots_double(k_inverse, p, k_row3, out.d, out.e);
    } else {
        out.d = dots(transpose(k_inverse), p);
        out.e = k_row3;
    }
    out.c_clip = convert<T, W>(Mirror ? -out.d : out.d);
    return out;
}

// k (as (z_f - z_n) k) and 1 / X_2 of the clip, or ok = false when a check
// fails or the numbers leave the safe range: the caller then returns its
// normalized reference form (cold, in src/oblique_clip.cpp and mirror.cpp),
// which refuses with the error text or, at a rounding boundary of a check,
// gives the result. Every quantity is invariant under p's scale, so p need
// not be unit.
template <class T>
struct ClipScalars {
    T span_k, inv_x2;
    T normal_squared; // |n|^2 of the plane as given (a mirror reflects with 2 / |n|^2)
    bool ok;
};
template <bool Mirror, class T>
FRUSTUM_HOT_INLINE ClipScalars<T> clip_scalars(const Cols<T>& inv, const V4<T>& p, const ClipPlane<T>& plane,
                                               const ClipDepth<T>& depth) {
    using W = typename Wider<T>::type;
    constexpr T k_sign = Mirror ? T(-1) : T(1);
    const T eps = std::numeric_limits<T>::epsilon();
    const T floor = T(64) * eps;

    // The plane's normal non-zero, and p . p finite (a NaN or infinite
    // coefficient, or an overflowing |p|^2, is the reference form's to refuse).
    // (|n|^2 and p . p share their first sum: the same sums as dot().)
    T normal_squared, p_dot_p;
    squares_xyz_xyzw(p, normal_squared, p_dot_p);
    // Eye strictly on the negative side, above the rounding floor of
    // p . M^-1_2 (eye_side_floor, eye_side.hpp: sum_i |p_i| |M^-1_2,i|).
    const T eye_side = depth.span * plane.c_clip[2];
    const T eye_floor = floor * abs_dot(p, inv.c[2]);

    // k = (m3 . Q) / (c . Q) (eq. 20-21, analytic-inverse-accuracy.md),
    // q = (sign c'_x, sign c'_y, z_f, 1) (erratum 2): both dot products from
    // d and e (in double), or from one Q = M^-1 q (same Q); see clip_plane.
    const V4<W> q = signs_xy_with(W(k_sign) * plane.d, W(depth.z_far));
    W a, b;
    if constexpr (std::is_same_v<W, double>) {
        b = dot<W>(plane.d, q);
        a = W(depth.span * k_sign) * dot<W>(plane.e, q);
    } else {
        const V4<T> big_q = mat_vec(inv, q);
        b = dot<T>(p, big_q);
        a = (depth.span * k_sign) * dot<T>(plane.e, big_q);
    }
    // Far corner on the plane's positive side, not a sliver: c' . q = k_sign b
    // above 64 eps sum |c'_i|. Formed in W; when W is wider than T the float
    // form of the test may differ by a few eps sum |c'_i|, so the fast form
    // asks for 72 (between 64 and 72 the reference form decides).
    const W scale = abs_sum(plane.d);
    const W corner_floor = (std::is_same_v<W, T> ? W(64) : W(72)) * W(eps);
    // All tests formed before one branch (& rather than &&: the compiler
    // would otherwise sink e and the scale past early exits, and spill).
    // The divisions only once their divisors are known non-zero (a plane
    // through the eye has c'_z = 0): no division by zero, also under
    // -fsanitize=float-divide-by-zero.
    const T largest = std::numeric_limits<T>::max();
    const bool usable = (normal_squared > T(0)) & (p_dot_p <= largest) &
                        (eye_side > eye_floor) &
                        (W(k_sign) * b > corner_floor * scale) & (std::abs(a) > W(0));
    if (!usable) {
        return {T(0), T(0), normal_squared, false};
    }
    // k and 1 / X_2 side by side: two independent divisions, not three in
    // series (X_2 = (z_f - z_n) k c'_z, so 1 / X_2 = b / (a c'_z)).
    const T span_k = T(a / b);
    const T inv_x2 = T(b / (a * W(plane.c_clip[2])));
    const bool normal_k = std::isnormal(span_k), normal_x2 = std::isnormal(inv_x2);
    return {span_k, inv_x2, normal_squared, bool(normal_k & normal_x2)};
}

// The clipped pair. The new matrix: the columns of the matrix being clipped
// (row3: their lanes 3) with row 2 replaced by eq. 22 generalized:
// (z_f - z_n) k c + z_n m3.
// The new inverse from inv, the inverse being clipped, by T^-1 (eq. 26-27),
// X = (z_f - z_n) k c' + z_n e3: column 2 / X_2, column j - (X_j / X_2)
// column 2, with X_j / X_2 = c'_j / c'_z for j = 0, 1 and
// c'_w / c'_z + z_n / X_2 for j = 3 (c' / c'_z does not wait for k, and has
// fewer roundings).
template <class T>
FRUSTUM_HOT_INLINE Result<MatrixPair<T>> clip_result(const OpenColumns<T>& matrix, const V4<T>& row3, const Cols<T>& inv,
                                                     const V4<T>& p, const V4<T>& c_clip, const ClipDepth<T>& depth,
                                                     const ClipScalars<T>& k, unsigned traits) {
    const V4<T> row2 = k.span_k * p + depth.z_near * row3;
    const Cols<T> m = with_rows23(matrix, row2, row3);
    const V4<T> c_over_cz = c_clip / splat(c_clip[2]);
    return PairFactory::keep_sign_result<T>(
        store<T>(m.c[0]), store<T>(m.c[1]), store<T>(m.c[2]), store<T>(m.c[3]),
        store<T>(inv.c[0] - c_over_cz[0] * inv.c[2]), store<T>(inv.c[1] - c_over_cz[1] * inv.c[2]),
        store<T>(inv.c[2] * k.inv_x2), store<T>(inv.c[3] - (c_over_cz[3] + depth.z_near * k.inv_x2) * inv.c[2]),
        traits);
}

} // namespace frustum::detail
