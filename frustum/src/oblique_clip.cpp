#include "frustum/oblique_clip.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/eye_side.hpp"
#include "frustum/detail/oblique_clip_core.hpp"
#include "frustum/detail/pair_factory.hpp"
#include "frustum/detail/pair_updates.hpp"
#include "frustum/reflect.hpp"

#include <cmath>
#include <limits>

namespace frustum {

namespace detail {

template <class T>
Result<MatrixPair<T>> clip_oblique_in_clip_space(const MatrixPair<T>& pair, const Vec4<T>& c, const Vec4<T>& c_clip,
                                                 const MatrixPair<T>& k_source, T k_sign, const char* function) {
    const Mat4<T>& inv = pair.inverse();
    const DepthRange depth = pair.depth();
    const T z_near = clip_z_near<T>(depth);
    const T z_far = clip_z_far<T>(depth);
    const T span = z_far - z_near;
    const T eps = std::numeric_limits<T>::epsilon();

    // Eye strictly on the negative side: (z_f - z_n) c'_z > 0, above the
    // rounding floor of c . M^-1_2 (eye_side.hpp), so the test is scale-free.
    const T eye_side = span * c_clip.z;
    const T floor = eye_side_floor(c, inv[2]);
    if (!(eye_side > floor)) {
        const bool through = std::abs(eye_side) <= floor;
        return error_text(function,
                          through ? "clip plane must not pass through the eye"
                                  : "the eye must be on the clip plane's negative side",
                          "plane=" + vector_text(c) + " eye_side=" + number(eye_side));
    }

    // The far corner on the plane's positive side (erratum 2), Q = M^-1 q.
    // (copysign: branch-free, the signs are unpredictable)
    const Vec4<T> q(std::copysign(T(1), c_clip.x), std::copysign(T(1), c_clip.y), z_far, T(1));
    const T c_dot_q = glm::dot(c_clip, q); // = c . Q
    const T scale = std::abs(c_clip.x) + std::abs(c_clip.y) + std::abs(c_clip.z) + std::abs(c_clip.w);
    if (!(c_dot_q > T(64) * eps * scale)) {
        return error_text(function, "clip plane leaves no part of the frustum visible",
                          "plane=" + vector_text(c) + " far_corner_side=" + number(c_dot_q));
    }
    // eq. 20-21: k = (m3 . Q) / (c . Q). In exact arithmetic m3 . Q = 1 and
    // c . Q = c' . q, but forming both from the same Q = M^-1 q cancels the
    // float disagreement between M and M^-1 (docs/analytic-inverse-accuracy.md).
    // Q is taken from k_source (see oblique_clip_core.hpp).
    const Vec4<T> big_q = k_source.inverse() * q;
    const T m3_q = k_sign * glm::dot(row(k_source.matrix(), 3), big_q);
    const T c_q = glm::dot(c, big_q);

    // New third row (eq. 22 generalized): (z_f - z_n) k c + z_n m3.
    // (column by column: entry 2 of column j is (z_f - z_n) k c_j + z_n m3_j)
    const T span_k = span * m3_q / c_q;
    Mat4<T> m = pair.matrix();
    for (int j = 0; j < 4; ++j) {
        m[j].z = span_k * c[j] + z_near * m[j].w;
    }

    // T^-1 (eq. 26-27, column form), X = (z_f - z_n) k c' + z_n e3:
    // column 2 / X_2, column j - (X_j / X_2) column 2.
    const Vec4<T> x = span_k * c_clip + Vec4<T>(T(0), T(0), T(0), z_near);
    const T inv_x2 = T(1) / x.z;
    Mat4<T> inv_new;
    inv_new[0] = inv[0] - (x.x * inv_x2) * inv[2];
    inv_new[1] = inv[1] - (x.y * inv_x2) * inv[2];
    inv_new[2] = inv[2] * inv_x2;
    inv_new[3] = inv[3] - (x.w * inv_x2) * inv[2];
    return PairFactory::keep_sign(m, inv_new, depth, pair.flips_winding());
}

template Result<MatrixPair<float>> clip_oblique_in_clip_space(const MatrixPair<float>&, const Vec4<float>&,
                                                              const Vec4<float>&, const MatrixPair<float>&,
                                                              float, const char*);
template Result<MatrixPair<double>> clip_oblique_in_clip_space(const MatrixPair<double>&, const Vec4<double>&,
                                                               const Vec4<double>&, const MatrixPair<double>&,
                                                               double, const char*);

} // namespace detail

namespace {

// clip_oblique()'s reference form (FRUSTUM_COLD, detail/pair_updates.hpp;
// reached from detail::clip_columns' checks): the unit plane, then the
// core above.
template <class T>
FRUSTUM_COLD Result<MatrixPair<T>> clip_oblique_reference(const MatrixPair<T>& pair, const Plane<T>& plane) {
    const auto unit = checked_unit_plane(plane, "clip_oblique");
    if (!unit) {
        return Error{unit.error()};
    }
    // The plane in clip space: c' = M^-T c, i.e. c'_j = c . (column j of M^-1).
    const Vec4<T>& c = unit->abcd;
    const Mat4<T>& inv = pair.inverse();
    const Vec4<T> c_clip(glm::dot(c, inv[0]), glm::dot(c, inv[1]), glm::dot(c, inv[2]), glm::dot(c, inv[3]));
    return detail::clip_oblique_in_clip_space(pair, c, c_clip, pair, T(1), "clip_oblique");
}

} // namespace

// The fast form: c' = M^-T p for the plane as given (every output of the
// clip is invariant under the plane's scale, k c and X are: no
// normalization), then detail::clip_scalars and clip_result. Every refusal,
// the plane's own included, goes through the reference form above.
template <class T>
Result<MatrixPair<T>> clip_oblique(const MatrixPair<T>& pair, const Plane<T>& plane) {
    const detail::Cols<T> m = detail::load(pair.matrix());
    const detail::Cols<T> inv = detail::load(pair.inverse());
    const detail::V4<T> p = detail::load(plane.abcd);
    const detail::V4<T> m_row3 = detail::transpose(m).c[3];
    const detail::ClipDepth<T> depth = detail::clip_depth<T>(pair.depth());
    const detail::ClipPlane<T> clip_plane = detail::clip_plane<false>(inv, m_row3, p);
    const detail::ClipScalars<T> k = detail::clip_scalars<false>(inv, p, clip_plane, depth);
    if (!k.ok) {
        return clip_oblique_reference(pair, plane);
    }
    return detail::clip_result(detail::open_columns(m), m_row3, inv, p, clip_plane.c_clip, depth, k,
                               detail::PairFactory::traits(pair));
}

template Result<MatrixPair<float>> clip_oblique(const MatrixPair<float>&, const Plane<float>&);
template Result<MatrixPair<double>> clip_oblique(const MatrixPair<double>&, const Plane<double>&);

} // namespace frustum
