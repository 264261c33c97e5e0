// Paper §4: a matrix pair from the side planes L, R, B, T and the near plane
// N. With K_l = 1 (eq. 10, in our inward convention
// L = -K_r R + K_b B + K_t T), the rows are
//   m0 = (L - K_r R)/2, m1 = (K_b B - K_t T)/2, m3 = (L + K_r R)/2,
//   m2 = z_n m3 + s K_n N                     (s = sign(z_f - z_n))
// and K_n places the far plane F = |z_f - z_n| m3 - K_n N, chosen either by a
// point on it (§4.1) or by the volume-growth loop (§4.2, erratum 12).
// The inverse is built from plane intersections (no matrix inversion).
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/plane.hpp"
#include "frustum/result.hpp"

#include <vector>

namespace frustum {

// Inward-positive planes in world space; they need not be normalized.
template <class T>
struct SidePlanes {
    Plane<T> left, right, bottom, top, near;
};

// §4.1 (eq. 11-12): the far plane passes through far_point, which must be
// in front of the eye and beyond the near plane:
//   K_n = |z_f - z_n| (m3 . Q) / (N . Q).
template <class T>
Result<MatrixPair<T>> from_planes(const SidePlanes<T>& planes, const Vec3<T>& far_point, DepthRange depth);

// §4.1 for several points: of the far planes F = |z_f - z_n| m3 - K_n N
// (they all contain the line where m3 and N meet), the nearest one that
// keeps every point inside: K_n = min_i |z_f - z_n| (m3 . Q_i) / (N . Q_i).
// Each point must be in front of the eye and beyond the near plane. Use it
// when the side planes are skewed (m3 not parallel to N, e.g. lens tiles):
// a single far point then tilts the far plane so much that it can cut the
// other edges close to the eye.
template <class T>
Result<MatrixPair<T>> from_planes(const SidePlanes<T>& planes, const std::vector<Vec3<T>>& far_points,
                                  DepthRange depth);

// §4.2 with the stop criterion corrected (docs/errata.md erratum 12): start at
// eq. 13, K_n = |z_f - z_n| (m3.xyz . N.xyz) / |N.xyz|^2, step by the paper's
// delta and double it, until every far corner C5..C8 is a finite point in
// front of the eye (w > 1e-6 |xyz| with w > 0 inside).
template <class T>
struct GrownFrustum {
    MatrixPair<T> pair;
    int iterations = 0; // how many times K_n grew (0: eq. 13 was already valid)
    T k_near = T(0);    // the final K_n
};
template <class T>
Result<GrownFrustum<T>> from_planes_volume_growth(const SidePlanes<T>& planes, DepthRange depth,
                                                  int max_iterations = 64);

} // namespace frustum
