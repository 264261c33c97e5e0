// Constructors of matrix pairs, each with a closed-form inverse (no matrix
// inversion). Right-handed eye space looking down -z, clip x, y in [-1, 1],
// clip z in the pair's DepthRange. `far_m = std::nullopt` is an infinite far
// plane (perspective only).
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/result.hpp"

#include <optional>

namespace frustum {

inline constexpr std::nullopt_t infinite_far = std::nullopt;

// Symmetric perspective; fovy_rad is the VERTICAL field of view in radians,
// in (0, pi); aspect = width / height > 0; 0 < near_m < far_m.
// Funnels into off_axis() with top = near tan(fovy/2), right = top aspect.
template <class T>
Result<MatrixPair<T>> perspective(T fovy_rad, T aspect, T near_m, std::optional<T> far_m, DepthRange depth);

// Off-axis perspective through the near-plane rectangle [left, right] x
// [bottom, top] at distance near_m (glFrustum's parameters).
//
//   | 2n/(r-l)    0      (r+l)/(r-l)  0 |        A = -(z_f f - z_n n)/(f - n)
//   |    0     2n/(t-b)  (t+b)/(t-b)  0 |        B = -n f (z_f - z_n)/(f - n)
//   |    0        0           A       B |   infinite f: A = -z_f, B = -n (z_f - z_n)
//   |    0        0          -1       0 |   (z_n, z_f: clip z of near and far)
//
// Paper eq. 28 is this matrix for DepthRange::MinusOneToOne, transposed.
template <class T>
Result<MatrixPair<T>> off_axis(T left, T right, T bottom, T top, T near_m, std::optional<T> far_m,
                               DepthRange depth);

// Orthographic box [left, right] x [bottom, top] x [-far_m, -near_m] in eye
// space; near_m may be negative or zero, far_m must exceed it. The eye (and
// so vanishing point O) is a point at infinity.
//
//   | 2/(r-l)    0       0   -(r+l)/(r-l) |     A = -(z_f - z_n)/(f - n)
//   |    0    2/(t-b)    0   -(t+b)/(t-b) |     B = z_n + A n
//   |    0       0       A         B      |
//   |    0       0       0         1      |
//
// Both constructors write their matrices with from_rows() (matrix_rows.hpp).
template <class T>
Result<MatrixPair<T>> orthographic(T left, T right, T bottom, T top, T near_m, T far_m, DepthRange depth);

// A view matrix looking from eye to target; up must not be parallel to the
// viewing direction. Rigid, so its inverse is the transpose form.
template <class T>
Result<RigidTransform<T>> look_at(const Vec3<T>& eye, const Vec3<T>& target, const Vec3<T>& up);

// View-projection: M = P V, M^-1 = V^-1 P^-1.
template <class T>
MatrixPair<T> compose(const MatrixPair<T>& projection, const RigidTransform<T>& view);

// An imported camera given by a bare matrix: the one place that computes an
// inverse numerically (once, through the adjugate, i.e. the intersection
// points of its planes), and refuses a singular or ill-conditioned matrix.
template <class T>
Result<MatrixPair<T>> from_matrix(const Mat4<T>& matrix, DepthRange depth);

} // namespace frustum
