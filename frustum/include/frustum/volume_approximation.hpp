// Paper §4.3: approximating a volume that no affine frustum captures exactly
// (a patch of a curved mirror: four reflected side planes and the tangent
// plane) by the frustum whose origin O best aligns its side planes with the
// target planes.
//
// Given target side planes T0..T3 (unit normals t_i) meeting the near plane
// in the points X0..X3 (clockwise), the side plane i of a frustum with
// origin O has the normal n_i = (X_i - O) x (X_i+1 - O). O maximizes
//   F(O) = sum_i F_i^2,  F_i = (n_i . t_i) / |n_i|  (= cos alpha_i).
// The paper's printed partial derivatives are wrong (docs/errata.md erratum 6);
// with d = X_i - X_i+1 the exact gradient is
//   grad(n_i . t_i) = d x t_i,   grad |n_i|^2 = 2 d x n_i,
//   grad F_i^2 = 2 (n.t)(d x t) / |n|^2 - 2 (n.t)^2 (d x n) / |n|^4,
// checked against finite differences in tests/math.
#pragma once

#include "frustum/from_planes.hpp"
#include "frustum/matrix_pair.hpp"
#include "frustum/plane.hpp"
#include "frustum/result.hpp"

#include <array>
#include <optional>

namespace frustum {

template <class T>
struct VolumeTarget {
    // X0..X3 on the near plane, clockwise as seen from the volume's origin:
    // top-left, top-right, bottom-right, bottom-left of the patch image.
    std::array<Vec3<T>, 4> near_points;
    std::array<Vec3<T>, 4> side_normals; // t0..t3, unit, inward (side i joins X_i and X_i+1)
    Plane<T> near;                       // positive side: the volume
};

// F(O) and its gradient.
template <class T>
T volume_objective(const VolumeTarget<T>& target, const Vec3<T>& origin, Vec3<T>* gradient = nullptr);

template <class T>
struct VolumeFit {
    Vec3<T> origin;     // the optimized O
    T objective = 0;    // F(O), at most 4
    int iterations = 0; // Newton solves taken
    MatrixPair<T> pair; // the frustum through O and X0..X3 with the near plane
};

// Newton's method on F with its analytic Hessian (n_i is affine in O:
// hess |n_i|^2 = 2 (|d|^2 I - d d^T), hess (n_i . t_i) = 0), damped
// (Levenberg-Marquardt) where H is not negative definite or a step does not
// gain, started at the point where T0, T1 and T2 meet (the paper's start;
// the centroid of X shifted back along the near normal when they do not
// meet in front of the near plane), or at `start` (a warm start: the
// neighbouring patch's origin or the previous frame's) when that is behind
// the near plane and F is no lower there. Stops when a step gains less than
// `tolerance` or after max_iterations solves. far_distance_m: how far beyond
// the near points, along the edges from O through X_i, the frustum reaches
// at least (the nearest far plane that keeps all four edges inside that
// long, as for lens tiles).
template <class T>
Result<VolumeFit<T>> fit_volume(const VolumeTarget<T>& target, T far_distance_m, DepthRange depth,
                                int max_iterations = 200, T tolerance = T(1e-10),
                                const std::optional<Vec3<T>>& start = std::nullopt);

} // namespace frustum
