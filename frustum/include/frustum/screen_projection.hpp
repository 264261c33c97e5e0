// Generalized perspective projection for a physical screen (Kooima,
// "Generalized Perspective Projection", 2008): the frustum from an eye
// through a planar rectangle, with the near plane parallel to the screen.
// The closed-form inverse comes from off_axis() and the rigid view, so
// nothing is inverted. mirror_rectangle(..., MirrorFit::Exact) is the same
// camera with eye = O' and near = the distance from O' to the mirror
// (both built by detail::window_camera(); tests/math/screen_projection_test.cpp
// checks the numbers).
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/result.hpp"

#include <optional>

namespace frustum {

// pa = lower_left, pb = lower_right, pc = upper_left, pe = eye:
//   vr = unit(pb - pa), vu = unit(pc - pa), vn = unit(vr × vu)
//   d  = -vn . (pa - pe)                  (eye-to-screen distance, > 0)
//   l = vr . (pa - pe) n / d,  r = vr . (pb - pe) n / d
//   b = vu . (pa - pe) n / d,  t = vu . (pc - pe) n / d
//   M = off_axis(l, r, b, t, n, f) * [vr vu vn]^T * translate(-pe)
// The eye must be in front of the screen (on the side vn points to), the
// edges pb - pa and pc - pa non-zero and perpendicular (|cos| <=
// perpendicular_tolerance(): 1e-6 in double, 1e-5 in float, where a
// rectangle computed in double and rounded to float is off by ~1e-6),
// 0 < near_m, and far_m (absent: infinite) > near_m.
template <class T>
constexpr T perpendicular_tolerance() {
    return sizeof(T) == sizeof(float) ? T(1e-5) : T(1e-6);
}

template <class T>
Result<MatrixPair<T>> screen_projection(const Vec3<T>& lower_left, const Vec3<T>& lower_right,
                                        const Vec3<T>& upper_left, const Vec3<T>& eye, T near_m,
                                        std::optional<T> far_m, DepthRange depth);

} // namespace frustum
