#include "frustum/queries.hpp"

#include "frustum/detail/depth_planes.hpp"
#include "frustum/detail/errors.hpp"
#include "frustum/detail/simd4.hpp"
#include "frustum/detail/tolerances.hpp"

#include <algorithm>
#include <cmath>

namespace frustum {

namespace {

// The sign that turns the depth rows so that z grows into the frustum.
template <class T>
T depth_sign(DepthRange depth) {
    return clip_z_span<T>(depth) > T(0) ? T(1) : T(-1);
}

// The near plane's row, eq. 1 with z on the near side: s (m2 - z_n m3).
template <class T>
Vec4<T> near_row(const Mat4<T>& m, DepthRange depth) {
    return depth_sign<T>(depth) * (row(m, 2) - clip_z_near<T>(depth) * row(m, 3));
}

// eq. 7: O = k m2' for any k != 0 (erratum 15), with the sign that puts the
// eye on the near plane's negative side: a finite eye gets w > 0 and an eye
// at infinity (orthographic) points back, away from the frustum.
template <class T>
Vec4<T> eye_column(const Vec4<T>& near, const Mat4<T>& inv) {
    return glm::dot(near, inv[2]) > T(0) ? -inv[2] : inv[2];
}

// eq. 8: C = x m0' + y m1' + z m2' + m3' (sums of inverse columns).
template <class T>
Vec4<T> corner_column(const Vec4<T>& clip, const Mat4<T>& inv) {
    return clip.x * inv[0] + clip.y * inv[1] + clip.z * inv[2] + inv[3];
}

} // namespace

namespace detail {

template <class T>
DepthPlanes<T> raw_depth_planes(const MatrixPair<T>& pair) {
    const Mat4<T>& m = pair.matrix();
    const Vec4<T> m2 = row(m, 2), m3 = row(m, 3);
    const DepthRange depth = pair.depth();
    DepthPlanes<T> p{Plane<T>(near_row(m, depth)), std::nullopt};
    const Plane<T> far(depth_sign<T>(depth) * (clip_z_far<T>(depth) * m3 - m2));
    // An infinite far plane has a (numerically) zero normal: erratum 9.
    const T scale = glm::length(Vec3<T>(m3)) + glm::length(Vec3<T>(m2));
    if (glm::length(far.normal()) > detail::rounding_floor<T>() * scale) {
        p.far = far;
    }
    return p;
}

} // namespace detail

template <class T>
FrustumPlanes<T> raw_planes(const MatrixPair<T>& pair) {
    const Mat4<T>& m = pair.matrix();
    const Vec4<T> m0 = row(m, 0), m1 = row(m, 1), m3 = row(m, 3);
    detail::DepthPlanes<T> depth = detail::raw_depth_planes(pair);
    FrustumPlanes<T> p;
    p.left = Plane<T>(m3 + m0);   // eq. 1: x >= -w
    p.right = Plane<T>(m3 - m0);  //        x <= w
    p.bottom = Plane<T>(m3 + m1); //        y >= -w
    p.top = Plane<T>(m3 - m1);    //        y <= w
    p.near = depth.near;
    p.far = depth.far;
    return p;
}

template <class T>
FrustumPlanes<T> planes(const MatrixPair<T>& pair) {
    FrustumPlanes<T> p = raw_planes(pair);
    p.left = p.left.normalized();
    p.right = p.right.normalized();
    p.bottom = p.bottom.normalized();
    p.top = p.top.normalized();
    p.near = p.near.normalized();
    if (p.far) {
        p.far = p.far->normalized();
    }
    return p;
}

template <class T>
DivisionPlanes<T> division_planes(const MatrixPair<T>& pair) {
    const Mat4<T>& m = pair.matrix();
    const T s = depth_sign<T>(pair.depth());
    // eq. 4: Dx = m0, Dy = m1, Dz = m2 - 0.5 m3 (z_mid = 0.5 in the paper's range)
    return {Plane<T>(row(m, 0)), Plane<T>(row(m, 1)),
            Plane<T>(s * (row(m, 2) - clip_z_mid<T>(pair.depth()) * row(m, 3)))};
}

template <class T>
Vec4<T> clip_corner(int index, DepthRange depth) {
    // eq. 8 order: (1,1), (-1,1), (-1,-1), (1,-1); near first, then far.
    static constexpr int xs[4] = {1, -1, -1, 1};
    static constexpr int ys[4] = {1, 1, -1, -1};
    const T z = index < 4 ? clip_z_near<T>(depth) : clip_z_far<T>(depth);
    return Vec4<T>(T(xs[index % 4]), T(ys[index % 4]), z, T(1));
}

template <class T>
KeyPoints<T> key_points(const MatrixPair<T>& pair) {
    const Mat4<T>& inv = pair.inverse();
    KeyPoints<T> k;
    for (int i = 0; i < 8; ++i) {
        k.corners[i] = corner_column(clip_corner<T>(i, pair.depth()), inv); // eq. 8
    }
    k.center = clip_z_mid<T>(pair.depth()) * inv[2] + inv[3]; // eq. 8: D = 0.5 m2' + m3'
    k.eye = eye_column(near_row(pair.matrix(), pair.depth()), inv); // eq. 7
    k.vanishing_y = inv[1]; // eq. 7: O1 = m1'
    k.vanishing_x = inv[0]; // eq. 7: O2 = m0'
    return k;
}

template <class T>
Vec4<T> to_point(const Vec4<T>& h, T relative_tolerance) {
    // Scale by the largest magnitude first so |xyz| neither overflows nor
    // underflows; the point it denotes is unchanged.
    const T largest = std::max(std::max(std::abs(h.x), std::abs(h.y)), std::max(std::abs(h.z), std::abs(h.w)));
    if (!(largest > T(0))) {
        return Vec4<T>(T(0));
    }
    const Vec4<T> s = h / largest;
    const Vec3<T> xyz(s);
    const T length = glm::length(xyz);
    if (std::abs(s.w) > relative_tolerance * length && s.w != T(0)) {
        return Vec4<T>(xyz / s.w, T(1)); // may overflow to inf for a point near infinity
    }
    return Vec4<T>(xyz / length, T(0));
}

template <class T>
std::optional<Vec3<T>> eye_point(const MatrixPair<T>& pair) {
    const Vec4<T> eye = to_point(key_points(pair).eye, infinity_tolerance<T>());
    if (eye.w != T(1)) {
        return std::nullopt;
    }
    return Vec3<T>(eye);
}

template <class T>
Result<T> near_distance(const MatrixPair<T>& pair) {
    const auto eye = eye_point(pair);
    if (!eye) {
        return detail::error_text("near_distance", "needs a perspective camera (finite eye)", "");
    }
    return std::abs(planes(pair).near.distance(*eye));
}

template <class T>
Result<T> far_distance(const MatrixPair<T>& pair) {
    const auto eye = eye_point(pair);
    if (!eye) {
        return detail::error_text("far_distance", "needs a perspective camera (finite eye)", "");
    }
    const auto all = planes(pair);
    if (!all.far) {
        return detail::error_text("far_distance", "needs a finite far plane", "");
    }
    return std::abs(all.far->distance(*eye));
}

namespace {

// to_point() for the moderate magnitudes of a camera's key points, four
// lanes at once: the same test (|w| > tolerance |xyz|, scale-free) and xyz / w
// in one rounding where to_point's rescaling by the largest magnitude
// (overflow safety) rounds twice; outside [2^-60, 2^60], where squares could
// leave float's range, to_point() itself.
template <class T>
Vec4<T> to_point_moderate(const Vec4<T>& h, T tolerance) {
    const T largest = std::max(std::max(std::abs(h.x), std::abs(h.y)), std::max(std::abs(h.z), std::abs(h.w)));
    if (!(largest > T(0x1p-60) && largest < T(0x1p60))) {
        return to_point(h, tolerance);
    }
    const T length = std::sqrt(h.x * h.x + h.y * h.y + h.z * h.z);
    if (!(std::abs(h.w) > tolerance * length)) {
        return to_point(h, tolerance); // a direction: to_point's unit form
    }
    const detail::V4<T> p = detail::load(h) / detail::splat(h.w);
    return Vec4<T>(Vec3<T>(detail::store<T>(p)), T(1));
}

} // namespace

template <class T>
Result<NearPlaneFrame<T>> near_plane_frame(const MatrixPair<T>& camera) {
    // key_points()' near corners and eye, the same expressions (same bits),
    // without its far corners and centre: lens_tiles calls this once per
    // grid (about 9% of a 4 x 4 grid's time, perf).
    const Mat4<T>& inv = camera.inverse();
    const DepthRange depth = camera.depth();
    const T tolerance = infinity_tolerance<T>();
    const Vec4<T> eye = to_point(eye_column(near_row(camera.matrix(), depth), inv), tolerance); // eye_point()
    if (eye.w != T(1)) {
        return detail::error_text("near_plane_frame", "needs a perspective camera (finite eye)", "");
    }
    Vec3<T> c[4];
    for (int i = 0; i < 4; ++i) {
        const Vec4<T> p = to_point_moderate(corner_column(clip_corner<T>(i, depth), inv), tolerance); // eq. 8
        if (p.w != T(1)) {
            return detail::error<T>("near_plane_frame", "near corner is not a finite point", {{"corner", T(i + 1)}});
        }
        c[i] = Vec3<T>(p);
    }
    NearPlaneFrame<T> frame;
    frame.center = (c[0] + c[1] + c[2] + c[3]) / T(4);
    const Vec3<T> half_x = (c[0] - c[1]) / T(2); // C1 - C2: along +x
    const Vec3<T> half_y = (c[0] - c[3]) / T(2); // C1 - C4: along +y
    frame.half_width_m = glm::length(half_x);
    frame.half_height_m = glm::length(half_y);
    frame.x_axis = half_x / frame.half_width_m;
    frame.y_axis = half_y / frame.half_height_m;
    frame.eye = Vec3<T>(eye);
    return frame;
}

#define FRUSTUM_INSTANTIATE(T)                                              \
    template FrustumPlanes<T> raw_planes(const MatrixPair<T>&);             \
    template detail::DepthPlanes<T> detail::raw_depth_planes(const MatrixPair<T>&); \
    template FrustumPlanes<T> planes(const MatrixPair<T>&);                 \
    template DivisionPlanes<T> division_planes(const MatrixPair<T>&);       \
    template Vec4<T> clip_corner<T>(int, DepthRange);                       \
    template KeyPoints<T> key_points(const MatrixPair<T>&);                 \
    template Vec4<T> to_point(const Vec4<T>&, T);                            \
    template std::optional<Vec3<T>> eye_point(const MatrixPair<T>&);         \
    template Result<T> near_distance(const MatrixPair<T>&);                  \
    template Result<T> far_distance(const MatrixPair<T>&);                   \
    template Result<NearPlaneFrame<T>> near_plane_frame(const MatrixPair<T>&);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
