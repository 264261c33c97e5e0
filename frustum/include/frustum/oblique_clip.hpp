// Paper §5.2, second step: the clip plane becomes the near plane (oblique
// near-plane clipping), with the inverse updated analytically (eq. 24-27).
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/plane.hpp"
#include "frustum/result.hpp"

namespace frustum {

// Keeps the plane's positive side. The eye must be strictly on its negative
// side (paper: c . O < 0), and some of the frustum must stay visible.
//
// Column form, depth range (z_n, z_f) (docs/errata.md erratum 2):
//   c' = M^-T c                      the plane in clip space
//   q  = (sgn c'_x, sgn c'_y, z_f, 1)  the far corner farthest on its side
//   k  = (m3 . Q) / (c . Q) = 1 / (c' . q)        with Q = M^-1 q
//   m2_new = (z_f - z_n) k c + z_n m3              the new third row
// So M_new = T M with row 2 of T being X = (z_f - z_n) k c' + z_n e3, and
//   inv_new col 2 = inv col 2 / X_2,
//   inv_new col j = inv col j - (X_j / X_2) inv col 2   (j = 0, 1, 3)
// which is the paper's T^-1 (eq. 26-27) transposed. The far plane then
// passes through Q; with an infinite far plane Q is a direction, and the new
// far plane is finite unless the clip plane is parallel to the old near
// plane (then it stays infinite). Row 3 (clip w) is unchanged, so the pair
// keeps its sign: w > 0 on the visible side.
template <class T>
Result<MatrixPair<T>> clip_oblique(const MatrixPair<T>& pair, const Plane<T>& plane);

} // namespace frustum
