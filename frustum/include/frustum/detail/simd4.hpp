// Four-wide vectors for the hot pair updates (GCC/Clang vector extensions:
// SSE on x86-64, NEON on aarch64, wasm SIMD or scalar code elsewhere). GLM
// built without intrinsics leaves its 4x4 arithmetic scalar; these helpers
// do the same arithmetic a whole column at a time, with GLM's order of sums
// (glm::dot: (t.x + t.y) + (t.z + t.w); M v: (m0 v0 + m1 v1) + (m2 v2 + m3 v3)),
// so results keep their bits.
#pragma once

#include "frustum/types.hpp"

#include <cstring>

// The double vectors are 32 bytes: without AVX GCC warns that passing them
// by value would change the ABI. They never cross a call (all inline).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace frustum::detail {

// (a trait, not an alias template: GCC drops vector_size on a dependent alias)
template <class T>
struct Vector4;
template <>
struct Vector4<float> {
    typedef float type __attribute__((vector_size(16)));
};
template <>
struct Vector4<double> {
    typedef double type __attribute__((vector_size(32)));
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

// glm::dot(a, b).
template <class T>
inline T dot(const V4<T>& a, const V4<T>& b) {
    const V4<T> t = a * b;
    return (t[0] + t[1]) + (t[2] + t[3]);
}

// M v as glm computes it.
template <class T>
inline V4<T> mat_vec(const Cols<T>& m, const V4<T>& v) {
    return (m.c[0] * v[0] + m.c[1] * v[1]) + (m.c[2] * v[2] + m.c[3] * v[3]);
}

// (glm::dot(v, m[0]), ..., glm::dot(v, m[3])), i.e. M^T v, from the rows.
template <class T>
inline V4<T> dots(const Cols<T>& rows, const V4<T>& v) {
    return (rows.c[0] * v[0] + rows.c[1] * v[1]) + (rows.c[2] * v[2] + rows.c[3] * v[3]);
}

} // namespace frustum::detail
