// Paper §5.2, first step: reflection of a frustum in a plane.
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/plane.hpp"
#include "frustum/result.hpp"

namespace frustum {

// eq. 16 in column form for a normalized plane c = (n, d):
//   R = | I - 2 n n^T   -2 d n |     R is its own inverse.
//       |     0            1   |
template <class T>
Mat4<T> reflection_matrix(const Plane<T>& unit_plane);

// P' = P R, P'^-1 = R P^-1 (the paper's R P and P^-1 R, transposed), done
// as rank-one updates: M' = M - 2 (M n) c^T, inv' = inv - 2 n (c^T inv).
// The plane need not be normalized; either side may face the eye. The
// result flips triangle winding (docs/errata.md erratum 3).
template <class T>
Result<MatrixPair<T>> reflect(const MatrixPair<T>& pair, const Plane<T>& plane);

// Checks shared by every operation that takes a plane: finite, non-zero
// normal. Returns the normalized plane.
template <class T>
Result<Plane<T>> checked_unit_plane(const Plane<T>& plane, const char* function);

// The same check without normalizing (for operations that are invariant
// under the plane's scale, like clip_oblique): empty on success.
template <class T>
Status check_plane(const Plane<T>& plane, const char* function);

} // namespace frustum
