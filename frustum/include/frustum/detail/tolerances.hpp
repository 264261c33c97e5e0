// The library's literal tolerances, named, each with the test it decides.
// Two kinds:
//   - rounding floors (a small multiple of eps times the size of the terms):
//     below them a value is indistinguishable from zero after rounding;
//   - geometric ratios (1e-6 of the sizes involved): inputs typed or rounded
//     by hand must still pass, but (nearly) parallel, coplanar or
//     degenerate configurations are refused before they divide by ~0.
// The same value serves float and double unless a line says otherwise.
// Public tolerances with their own documentation stay beside their API:
// infinity_tolerance (queries.hpp), rigid_tolerance (rigid.hpp), the
// screen_projection and fit_volume defaults.
#pragma once

#include <limits>

namespace frustum::detail {

// 64 eps: a result of a few dozen flops whose terms are of size 1 is zero
// below this (the far plane's normal of an infinite frustum, the eye's side
// of a clip plane, the turn of a collinear near-quad corner).
template <class T>
constexpr T rounding_floor() {
    return T(64) * std::numeric_limits<T>::epsilon();
}

// 16 eps: inverse_from_rows refuses a row whose dot with the point where the
// other three rows vanish is below this times the product of their lengths
// (|sin| of the angle: the row is dependent on the others).
template <class T>
constexpr T dependent_rows_floor() {
    return T(16) * std::numeric_limits<T>::epsilon();
}

// from_planes (eq. 9): the side planes meet in one point within 1e-4
// (float) / 1e-7 (double) of the size of the terms.
template <class T>
constexpr T concurrency_tolerance() {
    return sizeof(T) == sizeof(float) ? T(1e-4) : T(1e-7);
}

// 1e-6: the geometric ratio below which two directions count as parallel,
// a point as lying in a plane, or a far corner as at infinity:
//   from_planes: det of the right/bottom/top normals (they must span space),
//     near normal . projection direction, far corner w / |xyz|;
//   look_at: |forward x up| / |up|;
//   screen_projection: eye-to-screen distance / (width + height).
template <class T>
constexpr T degenerate_ratio() {
    return T(1e-6);
}

// 1e-9: fit_volume's three-plane intersection (Cramer) refuses unit
// normals whose determinant is below this (the corner is at infinity).
template <class T>
constexpr T corner_determinant_floor() {
    return T(1e-9);
}

// 1e-4: fit_volume's line search accepts a step when the objective grows
// by at least this fraction of step * |gradient|^2 (Armijo's constant).
template <class T>
constexpr T sufficient_increase() {
    return T(1e-4);
}

} // namespace frustum::detail
