#include "frustum/mirror.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/eye_side.hpp"
#include "frustum/detail/finite.hpp"
#include "frustum/detail/oblique_clip_core.hpp"
#include "frustum/detail/pair_updates.hpp"
#include "frustum/detail/window_camera.hpp"
#include "frustum/queries.hpp"
#include "frustum/reflect.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frustum {

namespace {

// mirror()'s reference form (FRUSTUM_COLD, detail/pair_updates.hpp):
// reflect, then the clip core with the unit plane.
template <class T>
FRUSTUM_COLD Result<MatrixPair<T>> mirror_reference(const MatrixPair<T>& pair, const Plane<T>& plane) {
    const auto unit = checked_unit_plane(plane, "mirror");
    if (!unit) {
        return Error{unit.error()};
    }
    auto reflected = reflect(pair, *unit);
    if (!reflected) {
        return Error{reflected.error()};
    }
    // The plane in the reflected pair's clip space, from the unreflected
    // inverse: (R M^-1)^T c = M^-T (R^T c) = -(M^-T c), because reflecting a
    // plane in itself only flips its sign.
    const Vec4<T> c_clip = -(glm::transpose(pair.inverse()) * unit->abcd);
    // The real eye must be in front of the mirror (its reflection then lies
    // behind the clip plane): say so in the mirror's terms, as culling_pair does.
    if (const auto error = detail::eye_in_front(pair, *unit, "mirror", "plane",
                                                "mirror plane must not pass through the eye",
                                                "the eye must be on the mirror plane's positive (front) side")) {
        return *error;
    }
    auto clipped = detail::clip_oblique_in_clip_space(*reflected, unit->abcd, c_clip, pair, T(-1), "mirror");
    if (!clipped) {
        return Error{clipped.error()};
    }
    return clipped;
}

} // namespace

// The fast form: the reference form's arithmetic in one inlined pass, the
// reflected columns straight into the clip step, with c' = -(M^-T c), Q and
// m3 . Q from the unreflected pair (oblique_clip_core.hpp). The plane is not
// normalized (the clip is scale-invariant) and reflect() uses
// R = I - (2 / |n|^2) n c^T. Every refusal goes through the reference form:
// its tests (the plane's, the eye in front of the mirror) are implied by
// the clip step's (the same scale-free eye test, and p . p finite).
template <class T>
Result<MatrixPair<T>> mirror(const MatrixPair<T>& pair, const Plane<T>& plane) {
    using detail::V4;
    const detail::Cols<T> m = detail::load(pair.matrix());
    const detail::Cols<T> inv = detail::load(pair.inverse());
    const V4<T> p = detail::load(plane.abcd);
    const V4<T> m_row3 = detail::transpose(m).c[3];
    const detail::ClipDepth<T> depth = detail::clip_depth<T>(pair.depth());
    const detail::ClipPlane<T> clip_plane = detail::clip_plane<true>(inv, m_row3, p);
    const detail::ClipScalars<T> k = detail::clip_scalars<true>(inv, p, clip_plane, depth);
    if (!k.ok) {
        return mirror_reference(pair, plane);
    }
    // reflect() (eq. 16) with R = I - (2 / |n|^2) n c^T: M R has columns
    // M_j - (2 p_j / |n|^2) M n (their lane 2 is replaced by the clip),
    // R M^-1 columns M^-1_j - (2 (p . M^-1_j) / |n|^2) n, and p . M^-1_j = -c'_j.
    // (n from p's lanes, |n|^2 from the clip step's: GCC otherwise keeps the
    // plane in memory and rebuilds both lane by lane, 15 instructions on
    // aarch64.)
    const V4<T> n = detail::with_lane<3>(p, T(0));
    const V4<T> m_n = detail::mat_vec(m, n);
    const T two_over_length_squared = T(2) / k.normal_squared;
    const V4<T> two_c = two_over_length_squared * p, two_c_inv = two_over_length_squared * clip_plane.c_clip;
    const detail::OpenColumns<T> reflected = detail::minus_outer(detail::open_columns(m), two_c, m_n);
    const V4<T> row3 = m_row3 - two_c * detail::lane<3>(m_n);
    detail::Cols<T> reflected_inv;
    for (int j = 0; j < 4; ++j) {
        reflected_inv.c[j] = inv.c[j] + two_c_inv[j] * n;
    }
    return detail::clip_result(reflected, row3, reflected_inv, p, clip_plane.c_clip, depth, k,
                               detail::PairFactory::flipped_traits(pair));
}

namespace {

using detail::finite3;

// The camera basis (rows of the view rotation) and near distance.
template <class T>
struct MirrorCamera {
    Vec3<T> i, j, k;
};

} // namespace

template <class T>
Result<MatrixPair<T>> mirror_rectangle(const Rectangle<T>& rect, const Vec3<T>& eye, T far_m, MirrorFit fit,
                                       DepthRange depth) {
    if (!finite3(rect.corner) || !finite3(rect.a1) || !finite3(rect.a2) || !finite3(eye) || !std::isfinite(far_m)) {
        return detail::error_text("mirror_rectangle", "corner, a1, a2, eye and far must be finite",
                                  "corner=" + detail::vector_text(rect.corner) + " a1=" + detail::vector_text(rect.a1) +
                                      " a2=" + detail::vector_text(rect.a2) + " eye=" + detail::vector_text(eye) +
                                      " far=" + detail::number(far_m));
    }
    const Vec3<T> normal_unnormalized = glm::cross(rect.a1, rect.a2);
    const T area = glm::length(normal_unnormalized);
    const T a1_length = glm::length(rect.a1);
    if (!(area > T(1e-6) * a1_length * glm::length(rect.a2)) || !(area > T(0))) {
        return detail::error_text("mirror_rectangle", "rectangle is degenerate (a1 and a2 parallel or zero)",
                                  "a1=" + detail::vector_text(rect.a1) + " a2=" + detail::vector_text(rect.a2));
    }
    // eq. 30: N = unit(a1 x a2), N_w = -N . P1, O' = R(N) O.
    const Vec3<T> normal = normal_unnormalized / area;
    const T eye_distance = glm::dot(normal, eye - rect.corner);
    if (!(std::abs(eye_distance) > T(1e-6) * (a1_length + glm::length(rect.a2)))) {
        return detail::error<T>("mirror_rectangle", "eye must not lie in the mirror's plane",
                                {{"eye_distance", eye_distance}});
    }
    const Vec3<T> reflected_eye = eye - T(2) * eye_distance * normal;
    const Vec3<T> corners[4] = {rect.corner, rect.corner + rect.a1, rect.corner + rect.a1 + rect.a2,
                                rect.corner + rect.a2}; // eq. 29

    MirrorCamera<T> cam;
    if (fit == MirrorFit::Paper) {
        const Vec3<T> center = rect.corner + (rect.a1 + rect.a2) / T(2); // eq. 31
        cam.k = glm::normalize(reflected_eye - center);                  // eq. 32
        cam.i = glm::normalize(glm::cross(rect.a1, cam.k));              // erratum 13
        cam.j = glm::cross(cam.k, cam.i);
    } else {
        cam.k = eye_distance > T(0) ? -normal : normal; // towards O', which is on the far side
        cam.j = rect.a1 / a1_length;
        cam.i = glm::cross(cam.j, cam.k);
    }

    // Corners in the camera frame: x, y and depth along -k.
    T x[4], y[4], d[4];
    for (int c = 0; c < 4; ++c) {
        const Vec3<T> v = corners[c] - reflected_eye;
        x[c] = glm::dot(v, cam.i);
        y[c] = glm::dot(v, cam.j);
        d[c] = -glm::dot(v, cam.k);
    }
    const T near_m = *std::min_element(d, d + 4);
    if (!(near_m > T(0))) {
        return detail::error<T>("mirror_rectangle", "every corner must be in front of the reflected eye",
                                {{"nearest_depth", near_m}});
    }
    T left = std::numeric_limits<T>::infinity(), right = -left, bottom = left, top = -left;
    for (int c = 0; c < 4; ++c) {
        // Project onto the near plane (the identity for the exact fit).
        const T px = x[c] * near_m / d[c];
        const T py = y[c] * near_m / d[c];
        left = std::min(left, px);
        right = std::max(right, px);
        bottom = std::min(bottom, py);
        top = std::max(top, py);
    }
    if (!(far_m > near_m)) {
        return detail::error<T>("mirror_rectangle", "far must exceed the near distance",
                                {{"near", near_m}, {"far", far_m}});
    }
    // eq. 28 and eq. 33: the window camera at O' with rows i, j, k. For the
    // exact fit this is screen_projection() of the mirror's bounding
    // rectangle (the mirror itself when a1 is perpendicular to a2) seen
    // from O', with near = O''s distance to the mirror.
    return detail::window_camera(
        detail::WindowCamera<T>{cam.i, cam.j, cam.k, reflected_eye, left, right, bottom, top, near_m, far_m}, depth,
        "frustum::mirror_rectangle()");
}

#define FRUSTUM_INSTANTIATE(T)                                                                     \
    template Result<MatrixPair<T>> mirror(const MatrixPair<T>&, const Plane<T>&);                  \
    template Result<MatrixPair<T>> mirror_rectangle(const Rectangle<T>&, const Vec3<T>&, T, MirrorFit, \
                                                    DepthRange);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
