// Planar mirrors: paper §5.2 (reflect + oblique clip) and §5.3 (a frustum
// through a rectangle seen from the reflected eye).
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/plane.hpp"
#include "frustum/result.hpp"

namespace frustum {

// reflect() then clip_oblique() by the same plane. The real eye must be on
// the plane's POSITIVE side (the mirror's front); the reflected eye then
// lies behind it and only what is in front of the mirror stays visible.
template <class T>
Result<MatrixPair<T>> mirror(const MatrixPair<T>& pair, const Plane<T>& plane);

// A rectangle P1, P1 + a1, P1 + a1 + a2, P1 + a2 (paper eq. 29).
template <class T>
struct Rectangle {
    Vec3<T> corner; // P1
    Vec3<T> a1, a2;
};

enum class MirrorFit {
    // §5.3 as printed (with erratum 13): the axis runs from the reflected
    // eye O' through the rectangle's centre C, k = unit(O' - C),
    // i = unit(a1 x k), j = k x i; the near plane is perpendicular to k
    // through the nearest corner. Unless the axis is perpendicular to the
    // mirror the near plane is not the mirror's, so geometry between the
    // mirror and O' can leak in (erratum 5): see tests/math. The four side
    // planes touch the rectangle (the window is the bounding box of the
    // projected corners), but the near plane misses the other three
    // corners: on the ordinary golden case (tests/golden, id
    // mirror-rect-paper-zo: corner (-1, 0, -2), a1 (2, 0, 0), a2 (0, 1.5, 0),
    // eye (0.3, 1, 2)) it passes 0.24, 0.09 and 0.15 m in front of them.
    // Use Exact to clip at the mirror.
    Paper,
    // Generalized off-axis perspective (Kooima): k = the mirror's normal on
    // O''s side, j = unit(a1), i = j x k, near = distance from O' to the
    // mirror; the near rectangle IS the mirror, nothing behind it leaks.
    Exact,
};

// The camera that looks from the reflected eye O' = R(N) eye (eq. 30)
// through the rectangle: an ordinary (unreflected) view of the scene from
// O', as eq. 28 with eq. 32-33's basis and shift. far_m is the eye-space
// depth of the far plane and must exceed the near distance.
template <class T>
Result<MatrixPair<T>> mirror_rectangle(const Rectangle<T>& rectangle, const Vec3<T>& eye, T far_m, MirrorFit fit,
                                       DepthRange depth);

} // namespace frustum
