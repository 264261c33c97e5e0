// What a matrix pair tells without any inversion (paper §3).
//
// Planes (§3.1, Gribb-Hartmann) come from the rows m0..m3 of M; key points
// (§3.2) from the columns m0'..m3' of M^-1. Both are given for the pair's own
// depth range (z_n, z_f): with s = sign(z_f - z_n),
//   L = m3 + m0, R = m3 - m0, B = m3 + m1, T = m3 - m1,
//   N = s (m2 - z_n m3), F = s (z_f m3 - m2)       (paper eq. 1, erratum 11)
// which for ZeroToOne are the paper's N = m2, F = m3 - m2.
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/plane.hpp"
#include "frustum/result.hpp"

#include <array>
#include <optional>

namespace frustum {

template <class T>
struct FrustumPlanes {
    Plane<T> left, right, bottom, top, near;
    std::optional<Plane<T>> far; // absent for an infinite far plane (erratum 9)

    // left, right, bottom, top, near, then far when present.
    std::array<std::optional<Plane<T>>, 6> as_array() const { return {left, right, bottom, top, near, far}; }
};

// The six planes, normalized (|normal| = 1) and inward-positive.
template <class T>
FrustumPlanes<T> planes(const MatrixPair<T>& pair);

// The same planes before normalization (exact rows of M combined): cheap,
// and what a shader or a culling loop that only needs signs should use.
template <class T>
FrustumPlanes<T> raw_planes(const MatrixPair<T>& pair);

// Division planes through the centre D (§3.1, eq. 4): Dx = m0, Dy = m1,
// Dz = s (m2 - z_mid m3), z_mid the centre of the depth range. Dz is
// positive towards the far plane. Not normalized (Dz of an orthographic or
// infinite frustum can still be used for signs).
template <class T>
struct DivisionPlanes {
    Plane<T> x, y, z;
};
template <class T>
DivisionPlanes<T> division_planes(const MatrixPair<T>& pair);

// Key points as homogeneous points (x, y, z, w) exactly as the inverse gives
// them (paper eq. 7-8). Use to_point() for the normalized form.
template <class T>
struct KeyPoints {
    std::array<Vec4<T>, 8> corners; // C1..C8: C1..C4 near (clip z = z_n), C5..C8 far
    Vec4<T> center;                 // D: clip (0, 0, z_mid, 1)
    Vec4<T> eye;                    // O  = ±m2', signed to lie behind the near plane (at infinity for orthographic)
    Vec4<T> vanishing_y;            // O1 = m1'
    Vec4<T> vanishing_x;            // O2 = m0'
};
template <class T>
KeyPoints<T> key_points(const MatrixPair<T>& pair);

// Clip-space corner i (0-based: C1 = 0) for the pair's depth range:
// (±1, ±1, z_n or z_f, 1) in the paper's order (eq. 8).
template <class T>
Vec4<T> clip_corner(int index, DepthRange depth);

// A homogeneous point in canonical form: w = 1 when finite, else w = 0 and
// |xyz| = 1 (a direction). `relative_tolerance` decides "at infinity":
// |w| <= tolerance |xyz|.
template <class T>
Vec4<T> to_point(const Vec4<T>& homogeneous, T relative_tolerance);

// The default tolerance for to_point: 1e-6 for float and 1e-12 for double.
template <class T>
constexpr T infinity_tolerance() {
    return sizeof(T) == sizeof(float) ? T(1e-6) : T(1e-12);
}

// The eye O as a Euclidean point: key_points(pair).eye in canonical form
// (to_point with infinity_tolerance<T>()). Empty for an orthographic pair,
// whose eye is at infinity.
template <class T>
std::optional<Vec3<T>> eye_point(const MatrixPair<T>& pair);

// Distance (metres, >= 0) from the eye to the near / far plane, measured
// along the plane's normal with the normalized planes(). Errors: no finite
// eye (orthographic); for far_distance also an infinite far plane.
template <class T>
Result<T> near_distance(const MatrixPair<T>& pair);
template <class T>
Result<T> far_distance(const MatrixPair<T>& pair);

// The near-plane frame of a perspective camera: centre, unit axes and half
// sizes (metres), from its near corners C1..C4 (§3.2). x_axis points from
// C2 to C1 (towards the right edge), y_axis from C4 to C1 (towards the top).
template <class T>
struct NearPlaneFrame {
    Vec3<T> center, x_axis, y_axis, eye;
    T half_width_m, half_height_m;
    Vec3<T> point(const Vec2<T>& plane_m) const { return center + plane_m.x * x_axis + plane_m.y * y_axis; }
    // Unit viewing direction, away from the eye for a right-handed frame.
    Vec3<T> forward() const { return glm::normalize(glm::cross(y_axis, x_axis)); }
};
// Errors: no finite eye, or a near corner at infinity.
template <class T>
Result<NearPlaneFrame<T>> near_plane_frame(const MatrixPair<T>& camera);

} // namespace frustum
