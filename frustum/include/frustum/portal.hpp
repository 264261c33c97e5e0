// Portals: the view through a pair of frames, entry and exit, with its
// inverse analytic (a rigid transform composed with the pair, then the
// paper's oblique clip, §5.2).
//
// Each portal is a Frame (rigid.hpp): origin, unit x right, unit y up, the
// normal n = x × y out of its front. A point that leaves the entry's front
// comes out of the exit's front, so the world behind the exit is seen
// through the entry as if the two frames were glued back to back:
//
//   T = F_entry H F_exit^-1,   H = diag(-1, 1, -1, 1)
//
// (H is a half turn about the frame's y axis: front becomes back, right
// becomes left, up stays up). T carries exit-side points to the entry side,
// so the virtual camera is M T (its eye is T^-1 eye, behind the exit), and
// clipping it obliquely by the exit plane (n_exit, -n_exit . origin_exit)
// keeps the exit's front visible and removes whatever lies behind the exit.
//
// A mirror is the special case entry = exit = the mirror's frame with the
// half turn H replaced by the reflection S = diag(1, 1, -1, 1) in the
// frame's own z: F S F^-1 is reflection_matrix(plane) (eq. 16), and the
// oblique clip by the same plane gives mirror() exactly (tests/math/
// portal_test.cpp checks it). H is a rotation (det +1), so a portal keeps
// the triangle winding; S has det -1, so a mirror flips it (erratum 3).
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/result.hpp"
#include "frustum/rigid.hpp"

namespace frustum {

// T = F_entry H F_exit^-1 and its inverse F_exit H F_entry^-1 (H = H^-1),
// both exact products of rigid matrices. Errors: a frame that is not
// finite, or whose axes are not unit length and orthogonal within 1e-6.
template <class T>
Result<RigidTransform<T>> portal_transform(const Frame<T>& entry, const Frame<T>& exit);

// The plane of a frame, positive on its front: (n, -n . origin).
template <class T>
Plane<T> frame_plane(const Frame<T>& frame) {
    // (+ 0 turns the -0 of cross products into 0, for readable messages)
    const Vec3<T> n = frame.normal() + Vec3<T>(T(0));
    return Plane<T>(Vec4<T>(n, -glm::dot(n, frame.origin) + T(0)));
}

// clip_oblique(compose(pair, T), frame_plane(exit)):
//   M' = (clip row 2 of) M T,   M'^-1 = T^-1 M^-1 with the clip's T^-1
// (eq. 24-27). The current eye must be on the entry's front (positive)
// side and not in its plane; the entry plane must leave some of the
// frustum visible after the carry.
template <class T>
Result<MatrixPair<T>> portal(const MatrixPair<T>& pair, const Frame<T>& entry, const Frame<T>& exit);

} // namespace frustum
