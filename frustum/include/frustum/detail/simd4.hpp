// Four-wide vectors for the hot pair updates (GCC/Clang vector extensions:
// SSE on x86-64, NEON on aarch64, wasm SIMD or scalar code elsewhere). GLM
// built without intrinsics leaves its 4x4 arithmetic scalar; these helpers
// do the same arithmetic a whole column at a time, with GLM's order of sums
// (glm::dot: (t.x + t.y) + (t.z + t.w); M v: (m0 v0 + m1 v1) + (m2 v2 + m3 v3)),
// so results keep their bits.
#pragma once

#include "frustum/types.hpp"

#include <climits>
#include <cmath>
#include <cstring>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__aarch64__)
#include <arm_neon.h>
#endif

namespace frustum::detail {

// double: two 16-byte halves. (A 32-byte GCC vector is split through
// memory by GCC when AVX is off, the x86-64 default: issue 14 measured
// double reflect 3x and mirror 5x slower than float that way.) Lane by
// lane the same IEEE operations as a four-wide vector, so the same bits.
typedef double Double2 __attribute__((vector_size(16)));
typedef long long Long2 __attribute__((vector_size(16)));
struct Mask4d {
    Long2 lo, hi;
    long long operator[](int i) const { return i < 2 ? lo[i] : hi[i - 2]; }
};
inline Mask4d operator&(const Mask4d& a, const Mask4d& b) {
    return {a.lo & b.lo, a.hi & b.hi};
}
struct Double4 {
    Double2 lo, hi;
    Double4() = default;
    Double4(double a, double b, double c, double d) : lo{a, b}, hi{c, d} {}
    Double4(Double2 l, Double2 h) : lo(l), hi(h) {}
    double operator[](int i) const { return i < 2 ? lo[i] : hi[i - 2]; }
};
#define FRUSTUM_DOUBLE4_OP(op)                                                                                    \
    inline Double4 operator op(const Double4& a, const Double4& b) { return {a.lo op b.lo, a.hi op b.hi}; }       \
    inline Double4 operator op(double a, const Double4& b) { return {a op b.lo, a op b.hi}; }                      \
    inline Double4 operator op(const Double4& a, double b) { return {a.lo op b, a.hi op b}; }
FRUSTUM_DOUBLE4_OP(+)
FRUSTUM_DOUBLE4_OP(-)
FRUSTUM_DOUBLE4_OP(*)
FRUSTUM_DOUBLE4_OP(/)
#undef FRUSTUM_DOUBLE4_OP
inline Double4 operator-(const Double4& a) {
    return {-a.lo, -a.hi};
}
inline Mask4d operator>(const Double4& a, const Double4& b) {
    return {a.lo > b.lo, a.hi > b.hi};
}
inline Mask4d operator<=(const Double4& a, const Double4& b) {
    return {a.lo <= b.lo, a.hi <= b.hi};
}

// (a trait, not an alias template: GCC drops vector_size on a dependent alias)
template <class T>
struct Vector4;
template <>
struct Vector4<float> {
    typedef float type __attribute__((vector_size(16)));
};
template <>
struct Vector4<double> {
    typedef Double4 type;
};
template <class T>
using V4 = typename Vector4<T>::type;

template <class T>
inline V4<T> load(const Vec4<T>& v) {
    V4<T> out;
    std::memcpy(&out, &v, sizeof out);
    return out;
}
template <class T>
inline Vec4<T> store(const V4<T>& v) {
    Vec4<T> out;
    std::memcpy(&out, &v, sizeof out);
    return out;
}
template <class T>
inline V4<T> splat(T s) {
    return V4<T>{s, s, s, s};
}

// Lane I of v in every lane (a shuffle, no trip through memory).
template <int I, class V>
inline V lane(const V& v) {
    return __builtin_shufflevector(v, v, I, I, I, I);
}
template <int I>
inline Double4 lane(const Double4& v) {
    const Double2 half = I < 2 ? v.lo : v.hi;
    const Double2 s = __builtin_shufflevector(half, half, I % 2, I % 2);
    return {s, s};
}

// v with lane I replaced by x.
template <int I, class V, class T>
inline V with_lane(V v, T x) {
    v[I] = x;
    return v;
}
template <int I, class T>
inline Double4 with_lane(Double4 v, T x) {
    if constexpr (I < 2) {
        v.lo[I] = x;
    } else {
        v.hi[I - 2] = x;
    }
    return v;
}

// True when every lane of a comparison mask is set (lanes are all ones or
// all zeros): the mask's 64-bit words ANDed, no per-lane extraction.
template <class M>
inline bool all_lanes(const M& mask) {
    static_assert(sizeof(M) % 8 == 0, "a mask of 64-bit words");
    unsigned long long words[sizeof(M) / 8];
    std::memcpy(words, &mask, sizeof words);
    unsigned long long all = ~0ull;
    for (const unsigned long long w : words) {
        all &= w;
    }
    return all == ~0ull;
}

// The type the oblique clip forms k in: double for float pairs on targets
// whose float multiply-adds are rounded twice (x86-64 SSE, wasm): every
// product of two floats is exact in double, so the dot products of k lose
// almost nothing to rounding (docs/analytic-inverse-accuracy.md). On aarch64,
// where GCC fuses them (one rounding per multiply-add), float: there the
// double lanes would cost more instructions than re-inverting
// (docs/performance.md).
template <class T>
struct Wider {
    typedef T type;
};
template <>
struct Wider<float> {
#if defined(__aarch64__)
    typedef float type;
#else
    typedef double type;
#endif
};
inline Double4 widen(const V4<float>& v) {
#if defined(__SSE2__)
    // cvtps2pd twice (GCC's generic conversion goes lane by lane through memory)
    return {_mm_cvtps_pd(v), _mm_cvtps_pd(_mm_movehl_ps(v, v))};
#elif defined(__aarch64__)
    return {vcvt_f64_f32(vget_low_f32(v)), vcvt_high_f64_f32(v)};
#else
    return {Double2{v[0], v[1]}, Double2{v[2], v[3]}};
#endif
}
inline const Double4& widen(const Double4& v) {
    return v;
}
// Back to the pair's type (round to nearest).
template <class T>
inline V4<T> narrow(const Double4& v);
template <>
inline V4<float> narrow<float>(const Double4& v) {
#if defined(__SSE2__)
    return _mm_movelh_ps(_mm_cvtpd_ps(v.lo), _mm_cvtpd_ps(v.hi));
#elif defined(__aarch64__)
    return vcvt_high_f32_f64(vcvt_f32_f64(v.lo), v.hi);
#else
    return V4<float>{float(v.lo[0]), float(v.lo[1]), float(v.hi[0]), float(v.hi[1])};
#endif
}
template <>
inline V4<double> narrow<double>(const Double4& v) {
    return v;
}

// v in the type W (float <-> double, or unchanged).
template <class W, class T>
inline V4<W> convert(const V4<T>& v) {
    if constexpr (std::is_same_v<W, T>) {
        return v;
    } else if constexpr (std::is_same_v<W, double>) {
        return widen(v);
    } else {
        return narrow<W>(v);
    }
}

// (sign(v_0) 1, sign(v_1) 1, z, 1): copysign on lanes 0 and 1 as bit
// operations on the whole vector (the same values as std::copysign).
inline V4<float> signs_xy_with(const V4<float>& v, float z) {
    typedef int Int4 __attribute__((vector_size(16)));
    const Int4 sign_bits = (Int4)v & Int4{INT_MIN, INT_MIN, 0, 0}; // vector casts reinterpret the bits
    return (V4<float>)((Int4)V4<float>{1.0f, 1.0f, z, 1.0f} | sign_bits);
}
inline Double4 signs_xy_with(const Double4& v, double z) {
    const Long2 sign_bits = (Long2)v.lo & Long2{LLONG_MIN, LLONG_MIN};
    return {(Double2)((Long2)Double2{1.0, 1.0} | sign_bits), Double2{z, 1.0}};
}

// A matrix as four column vectors.
template <class T>
struct Cols {
    V4<T> c[4];
};
template <class T>
inline Cols<T> load(const Mat4<T>& m) {
    return {{load(m[0]), load(m[1]), load(m[2]), load(m[3])}};
}

// Rows of a column-major matrix: transpose(m).c[i] = row i of m.
template <class T>
inline Cols<T> transpose(const Cols<T>& m) {
    const V4<T> t0 = __builtin_shufflevector(m.c[0], m.c[1], 0, 4, 1, 5);
    const V4<T> t1 = __builtin_shufflevector(m.c[2], m.c[3], 0, 4, 1, 5);
    const V4<T> t2 = __builtin_shufflevector(m.c[0], m.c[1], 2, 6, 3, 7);
    const V4<T> t3 = __builtin_shufflevector(m.c[2], m.c[3], 2, 6, 3, 7);
    return {{__builtin_shufflevector(t0, t1, 0, 1, 4, 5), __builtin_shufflevector(t0, t1, 2, 3, 6, 7),
             __builtin_shufflevector(t2, t3, 0, 1, 4, 5), __builtin_shufflevector(t2, t3, 2, 3, 6, 7)}};
}

inline Cols<double> transpose(const Cols<double>& m) {
    const auto& c = m.c;
    return {{Double4(__builtin_shufflevector(c[0].lo, c[1].lo, 0, 2), __builtin_shufflevector(c[2].lo, c[3].lo, 0, 2)),
             Double4(__builtin_shufflevector(c[0].lo, c[1].lo, 1, 3), __builtin_shufflevector(c[2].lo, c[3].lo, 1, 3)),
             Double4(__builtin_shufflevector(c[0].hi, c[1].hi, 0, 2), __builtin_shufflevector(c[2].hi, c[3].hi, 0, 2)),
             Double4(__builtin_shufflevector(c[0].hi, c[1].hi, 1, 3), __builtin_shufflevector(c[2].hi, c[3].hi, 1, 3))}};
}

// (t0 + t1) + (t2 + t3), glm::dot's order of sums. NEON: one vector and
// one scalar pairwise add (GCC writes the generic form as a lane reversal,
// an add, a lane move and an add); SSE: one shuffle and add, then lanes 0
// and 2.
inline float sum4(const V4<float>& t) {
#if defined(__aarch64__)
    return vpadds_f32(vget_low_f32(vpaddq_f32((float32x4_t)t, (float32x4_t)t)));
#else
    const V4<float> pairs = t + __builtin_shufflevector(t, t, 1, 0, 3, 2);
    return pairs[0] + pairs[2];
#endif
}

// v . v over lanes 0-2 and over all four lanes, sharing their first sum:
// xyz = (s0 + s1) + s2, xyzw = (s0 + s1) + (s2 + s3) for s = v * v (as
// glm::dot(vec3) and glm::dot(vec4) sum).
template <class V, class T>
inline void squares_xyz_xyzw(const V& v, T& xyz, T& xyzw) {
    const V s = v * v;
#if defined(__aarch64__)
    if constexpr (std::is_same_v<T, float>) {
        const float32x4_t pairs = vpaddq_f32((float32x4_t)s, (float32x4_t)s); // (s0 + s1, s2 + s3, ...)
        xyz = vgetq_lane_f32(pairs, 0) + s[2];
        xyzw = vpadds_f32(vget_low_f32(pairs));
        return;
    }
#endif
    const T s01 = s[0] + s[1];
    xyz = s01 + s[2];
    xyzw = s01 + (s[2] + s[3]);
}

// glm::dot(a, b): (t0 + t1) + (t2 + t3).
inline float dot(const V4<float>& a, const V4<float>& b) {
    return sum4(a * b);
}
inline double dot(const Double4& a, const Double4& b) {
    const Double4 t = a * b;
    return (t.lo[0] + t.lo[1]) + (t.hi[0] + t.hi[1]);
}
template <class T>
inline T dot(const V4<T>& a, const V4<T>& b) {
    return dot(a, b);
}

// |v_0| + |v_1| + |v_2| + |v_3|. float: summed as dot() sums, (|v_0| +
// |v_1|) + (|v_2| + |v_3|), the sign bits cleared in one vector operation
// (on NEON: one bic and two pairwise adds). double: in lane order, which on
// SSE2's two-lane halves takes no shuffles.
inline float abs_sum(const V4<float>& v) {
    typedef int Int4 __attribute__((vector_size(16)));
    return sum4((V4<float>)((Int4)v & Int4{INT_MAX, INT_MAX, INT_MAX, INT_MAX}));
}
inline double abs_sum(const Double4& v) {
    return ((std::abs(v[0]) + std::abs(v[1])) + std::abs(v[2])) + std::abs(v[3]);
}

// |a_0 b_0| + |a_1 b_1| + |a_2 b_2| + |a_3 b_3| (= sum_i |a_i| |b_i|, a
// rounding floor: the order of sums is not kept).
inline float abs_dot(const V4<float>& a, const V4<float>& b) {
    return abs_sum(a * b);
}
inline double abs_dot(const Double4& a, const Double4& b) {
    return abs_sum(a * b);
}

// M v as glm computes it.
template <class T>
inline V4<T> mat_vec(const Cols<T>& m, const V4<T>& v) {
    if constexpr (std::is_same_v<T, float>) { // splats by shuffles (GCC otherwise goes through memory on NEON)
        return (m.c[0] * lane<0>(v) + m.c[1] * lane<1>(v)) + (m.c[2] * lane<2>(v) + m.c[3] * lane<3>(v));
    } else {
        return (m.c[0] * v[0] + m.c[1] * v[1]) + (m.c[2] * v[2] + m.c[3] * v[3]);
    }
}

// (glm::dot(v, m[0]), ..., glm::dot(v, m[3])), i.e. M^T v, from the rows.
template <class T>
inline V4<T> dots(const Cols<T>& rows, const V4<T>& v) {
    return mat_vec(rows, v);
}


// Lanes 0 and 1 of a and of b: (a_0, a_1, b_0, b_1). The x and y of two
// columns side by side (the oblique clip rewrites only their lane 2).
inline V4<float> xy_pairs(const V4<float>& a, const V4<float>& b) {
    return __builtin_shufflevector(a, b, 0, 1, 4, 5);
}
inline Double4 xy_pairs(const Double4& a, const Double4& b) {
    return {a.lo, b.lo};
}
// (v_I, v_I, v_J, v_J): each column's factor beside its xy pair.
template <int I, int J>
inline V4<float> lane_pairs(const V4<float>& v) {
    return __builtin_shufflevector(v, v, I, I, J, J);
}
template <int I, int J>
inline Double4 lane_pairs(const Double4& v) {
    const Double2 a = I < 2 ? v.lo : v.hi, b = J < 2 ? v.lo : v.hi;
    return {__builtin_shufflevector(a, a, I % 2, I % 2), __builtin_shufflevector(b, b, J % 2, J % 2)};
}

// Columns from lanes 0-1 (xy01 = xy_pairs(col 0, col 1), xy23 likewise)
// and rows 2 and 3: column j = (x_j, y_j, row2_j, row3_j). Six shuffles
// for four lane inserts (SSE2 has no insertps).
inline Cols<float> columns_from_rows23(const V4<float>& xy01, const V4<float>& xy23, const V4<float>& row2,
                                       const V4<float>& row3) {
    const V4<float> low = __builtin_shufflevector(row2, row3, 0, 4, 1, 5);  // (r2_0, r3_0, r2_1, r3_1)
    const V4<float> high = __builtin_shufflevector(row2, row3, 2, 6, 3, 7); // (r2_2, r3_2, r2_3, r3_3)
    return {{__builtin_shufflevector(xy01, low, 0, 1, 4, 5), __builtin_shufflevector(xy01, low, 2, 3, 6, 7),
             __builtin_shufflevector(xy23, high, 0, 1, 4, 5), __builtin_shufflevector(xy23, high, 2, 3, 6, 7)}};
}
inline Cols<double> columns_from_rows23(const Double4& xy01, const Double4& xy23, const Double4& row2,
                                        const Double4& row3) {
    return {{Double4(xy01.lo, __builtin_shufflevector(row2.lo, row3.lo, 0, 2)),
             Double4(xy01.hi, __builtin_shufflevector(row2.lo, row3.lo, 1, 3)),
             Double4(xy23.lo, __builtin_shufflevector(row2.hi, row3.hi, 0, 2)),
             Double4(xy23.hi, __builtin_shufflevector(row2.hi, row3.hi, 1, 3))}};
}

// The columns of a matrix whose row 2 is still to be written (the oblique
// clip replaces it): lanes 0 and 1 of each column, lane 3 given as the row
// apart. SSE2, which has no lane insert, keeps the xy pairs of columns 0-1
// and 2-3 and rebuilds the columns from them and the rows (six shuffles for
// four inserts); NEON keeps the whole columns and inserts the four lanes.
template <class T>
struct OpenColumns {
    static constexpr bool whole = false;
    V4<T> xy01, xy23; // xy_pairs(column 0, column 1), xy_pairs(column 2, column 3)
};
#if defined(__aarch64__)
template <>
struct OpenColumns<float> {
    static constexpr bool whole = true;
    Cols<float> m; // lane 2 unused
};
#endif
template <class T>
inline OpenColumns<T> open_columns(const Cols<T>& m) {
    if constexpr (OpenColumns<T>::whole) {
        return {m};
    } else {
        return {xy_pairs(m.c[0], m.c[1]), xy_pairs(m.c[2], m.c[3])};
    }
}
// Column j minus u_j v (a rank-one update). Lane 2 is written afterwards
// by with_rows23; the SSE2 form computes lanes 0 and 1 only, its lane 3
// comes from the row handed to with_rows23.
template <class T>
inline OpenColumns<T> minus_outer(const OpenColumns<T>& m, const V4<T>& u, const V4<T>& v) {
    if constexpr (OpenColumns<T>::whole) {
        OpenColumns<T> out;
        for (int j = 0; j < 4; ++j) {
            out.m.c[j] = m.m.c[j] - u[j] * v;
        }
        return out;
    } else {
        const V4<T> v_xy = xy_pairs(v, v);
        return {m.xy01 - lane_pairs<0, 1>(u) * v_xy, m.xy23 - lane_pairs<2, 3>(u) * v_xy};
    }
}
// Column j = (x_j, y_j, row2_j, row3_j).
template <class T>
inline Cols<T> with_rows23(const OpenColumns<T>& m, const V4<T>& row2, const V4<T>& row3) {
    if constexpr (OpenColumns<T>::whole) {
        (void)row3; // lane 3 of the columns already
        return {{with_lane<2>(m.m.c[0], row2[0]), with_lane<2>(m.m.c[1], row2[1]), with_lane<2>(m.m.c[2], row2[2]),
                 with_lane<2>(m.m.c[3], row2[3])}};
    } else {
        return columns_from_rows23(m.xy01, m.xy23, row2, row3);
    }
}

// (a . cols_j)_j and (b . cols_j)_j in double, column by column: the halves
// (t0 + t2, t1 + t3) in one multiply-add of 2-lane vectors, then the
// halves' sums of two columns in one addition (no transpose, no splats).
// For float inputs every product is exact in double.
template <class T>
inline void column_dots_double(const Cols<T>& cols, const V4<T>& a, const V4<T>& b, Double4& a_dots,
                               Double4& b_dots) {
    const Double4 aw = widen(a), bw = widen(b);
    Double2 sa[4], sb[4];
    for (int j = 0; j < 4; ++j) {
        const Double4 c = widen(cols.c[j]);
        sa[j] = c.lo * aw.lo + c.hi * aw.hi;
        sb[j] = c.lo * bw.lo + c.hi * bw.hi;
    }
    const auto sums = [](const Double2& x, const Double2& y) {
        return __builtin_shufflevector(x, y, 0, 2) + __builtin_shufflevector(x, y, 1, 3);
    };
    a_dots = {sums(sa[0], sa[1]), sums(sa[2], sa[3])};
    b_dots = {sums(sb[0], sb[1]), sums(sb[2], sb[3])};
}

} // namespace frustum::detail
