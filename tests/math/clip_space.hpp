// Clip-space helpers of the math suite: un-projection, inside tests,
// random clip points and planes through the frustum, and row literals.
#pragma once

#include "random_cameras.hpp"
#include "support_basics.hpp"

namespace mtest {

// World (homogeneous) point of a clip-space point.
template <class T>
Vec4<T> unproject(const MatrixPair<T>& p, const Vec4<T>& clip) {
    return p.inverse() * clip;
}

// Clip z of a fraction t in [0, 1] of the way from the near to the far
// plane (in clip z, not in eye depth).
template <class T>
T clip_z_at(DepthRange d, double t) {
    return T(frustum::clip_z_near<double>(d) + t * frustum::clip_z_span<double>(d));
}

// Inside test in clip space with a margin (|x| <= w etc.; z between the
// depth range's ends, whatever their order).
template <class T>
bool clip_inside(const Vec4<T>& c, DepthRange d, double margin = 0) {
    const double w = c.w;
    if (!(w > 0)) return false;
    const double zn = frustum::clip_z_near<double>(d), zf = frustum::clip_z_far<double>(d);
    const double lo = std::min(zn, zf), hi = std::max(zn, zf);
    const double m = margin * w;
    return std::abs(double(c.x)) <= w - m && std::abs(double(c.y)) <= w - m && double(c.z) >= lo * w + m &&
           double(c.z) <= hi * w - m;
}

// A plane's value at a world point given homogeneously with w > 0.
template <class T>
double side(const Plane<T>& plane, const Vec4<T>& h) {
    return double(plane.evaluate(h)) / double(h.w);
}

// A random clip-space point strictly inside the clip box: x, y within
// [-1 + margin, 1 - margin], z a fraction margin..1-margin of the way from
// z_near to z_far, w = 1.
inline glm::dvec4 random_clip_point(Random& rng, DepthRange d, double margin) {
    return {rng.uniform(-1 + margin, 1 - margin), rng.uniform(-1 + margin, 1 - margin),
            clip_z_at<double>(d, rng.uniform(margin, 1 - margin)), 1};
}

// The plane c (world) seen in the pair's clip space: c'_j = c . (column j
// of M^-1), so that c' . (M p) = c . p.
template <class T>
glm::dvec4 clip_space_plane(const MatrixPair<T>& pair, const Plane<T>& c) {
    const glm::dmat4 inv(pair.inverse());
    const glm::dvec4 cw(c.abcd);
    return {glm::dot(cw, inv[0]), glm::dot(cw, inv[1]), glm::dot(cw, inv[2]), glm::dot(cw, inv[3])};
}

// A random world plane through a random point inside the pair's frustum,
// made in clip space (c' = (n', -n'.p0), world c = M^T c', normalized).
// eye_behind: the eye on the plane's negative side (clip_oblique's rule:
// (z_f - z_n) c'_z > 0); otherwise on its positive side (mirror's rule).
// The clip-space tilt is at most 45 degrees off the z axis in x and y.
template <class T>
Plane<T> random_plane_through(Random& rng, const MatrixPair<T>& pair, bool eye_behind) {
    const DepthRange d = pair.depth();
    const double s = frustum::clip_z_span<double>(d) > 0 ? 1 : -1;
    const glm::dvec4 p0 = random_clip_point(rng, d, 0.1);
    // One draw per statement (argument order is unspecified), z first.
    const double n_z = (eye_behind ? s : -s) * rng.uniform(0.2, 1);
    const double n_y = rng.uniform(-1, 1);
    const double n_x = rng.uniform(-1, 1);
    const glm::dvec3 n(n_x, n_y, n_z);
    const glm::dvec4 clip_plane(n, -glm::dot(n, glm::dvec3(p0)));
    const glm::dvec4 c = glm::transpose(glm::dmat4(pair.matrix())) * clip_plane;
    return Plane<T>(Vec4<T>(c / glm::length(glm::dvec3(c))));
}

// Where the plane cuts the four side edges of the frustum: the smallest
// w / |h| of the four cut points h (homogeneous, world). Positive: all four
// in front of the eye (the near face is then a bounded convex quad);
// negative: some edge meets the plane only behind the eye. The edge
// x = +-w, y = +-w meets c' at clip z* = -(c'_x x + c'_y y + c'_w)/c'_z.
template <class T>
double edge_cut_margin(const MatrixPair<T>& pair, const Plane<T>& c) {
    const glm::dvec4 cc = clip_space_plane(pair, c);
    const glm::dmat4 inv(pair.inverse());
    if (cc.z == 0) return 0;
    double worst = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 4; ++j) {
        const glm::dvec4 q = frustum::clip_corner<double>(j, pair.depth());
        const double z = -(cc.x * q.x + cc.y * q.y + cc.w) / cc.z;
        const glm::dvec4 h = inv * glm::dvec4(q.x, q.y, z, 1);
        worst = std::min(worst, h.w / glm::length(h));
    }
    return worst;
}
template <class T>
bool cuts_all_edges_in_front(const MatrixPair<T>& pair, const Plane<T>& c) {
    return edge_cut_margin(pair, c) > 0;
}

// Row literals: frustum::from_rows (matrix_rows.hpp), as the library writes them.
using frustum::from_rows;

} // namespace mtest

