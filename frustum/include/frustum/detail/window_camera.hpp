// The one exact core of screen_projection() and mirror_rectangle(...,
// MirrorFit::Exact) (and of the paper fit's last step): a camera at an eye
// with orthonormal axes i (right), j (up), k (back: from the window towards
// the eye) whose near plane, near_m in front of the eye, holds the window
// [left, right] x [bottom, top] (eye-space x, y on that plane):
//   M = off_axis(left, right, bottom, top, near, far)   (eq. 28)
//     * [i j k]^T * translate(-eye)                      (eq. 33, Kooima's M^T)
// Both inverses are closed-form (off_axis() and the rigid view), nothing is
// inverted. Internal: the callers have checked the eye, the axes and the
// window; off_axis()'s own refusals come back prefixed with `caller`.
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/projection.hpp"
#include "frustum/result.hpp"
#include "frustum/rigid.hpp"

#include <optional>
#include <string_view>

namespace frustum::detail {

template <class T>
struct WindowCamera {
    Vec3<T> i, j, k; // right, up, back; orthonormal, right-handed
    Vec3<T> eye_m;
    T left, right, bottom, top; // the window on the near plane, eye space
    T near_m;
    std::optional<T> far_m; // absent: infinite
};

template <class T>
Result<MatrixPair<T>> window_camera(const WindowCamera<T>& c, DepthRange depth, std::string_view caller) {
    auto projection = off_axis(c.left, c.right, c.bottom, c.top, c.near_m, c.far_m, depth);
    if (!projection) {
        return projection.take_error_in(caller);
    }
    Mat3<T> rotation; // rows i, j, k
    for (int col = 0; col < 3; ++col) {
        rotation[col] = Vec3<T>(c.i[col], c.j[col], c.k[col]);
    }
    const auto view = RigidTransform<T>::from_rotation_translation(rotation, -(rotation * c.eye_m));
    return compose(*projection, view);
}

} // namespace frustum::detail
