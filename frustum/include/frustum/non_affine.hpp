// Paper §6: a frustum given by six arbitrary planes, which no 4x4 matrix may
// represent (its opposite planes need not meet on a common line with the
// others). A point X maps to
//   u = d_l / (d_l + d_r),  v = d_t / (d_t + d_b),  s = d_n / (d_n + d_f)   (eq. 36)
// with d_i the signed distance to plane i, normals OUTWARD as the paper says
// (so d_i < 0 inside and u, v, s run over [0, 1] inside). We map that to the
// pipeline's clip space: x = 2u - 1 (left -1), y = 1 - 2v (top +1), z from
// the depth range's near (s = 0) to far (s = 1), w = 1.
//
// The denominators vanish where a point is equally far outside one plane as
// it is inside the opposite one: off the frustum, but a triangle with one
// vertex inside and one there is torn apart. to_clip() refuses points whose
// denominators are not safely negative; see docs/non-affine.md for the remedy
// used by the renderer (cull or subdivide such triangles).
#pragma once

#include "frustum/depth_range.hpp"
#include "frustum/plane.hpp"
#include "frustum/result.hpp"

#include <optional>

namespace frustum {

template <class T>
class NonAffineFrustum {
public:
    // Planes with outward normals (they need not be normalized; they are
    // normalized here). Checked: finite, non-zero normals, and the point
    // `inside` strictly inside all six.
    static Result<NonAffineFrustum> from_planes(const Plane<T>& left, const Plane<T>& right, const Plane<T>& bottom,
                                                const Plane<T>& top, const Plane<T>& near, const Plane<T>& far,
                                                const Vec3<T>& inside, DepthRange depth);

    // (u, v, s) of eq. 36, or nothing where a denominator is >= -guard (the
    // degenerate set and its neighbourhood; guard in metres of distance).
    std::optional<Vec3<T>> parameters(const Vec3<T>& point, T guard_m) const;

    // Clip coordinates (w = 1) for the pipeline, or nothing as above.
    std::optional<Vec4<T>> to_clip(const Vec3<T>& point, T guard_m) const;

    // The three denominators d_l + d_r, d_t + d_b, d_n + d_f (negative inside).
    Vec3<T> denominators(const Vec3<T>& point) const;

    // Planes in order left, right, bottom, top, near, far (unit, outward).
    const Plane<T>& plane(int index) const { return planes_[index]; }
    DepthRange depth() const { return depth_; }

private:
    Plane<T> planes_[6];
    DepthRange depth_ = DepthRange::ZeroToOne;
};

} // namespace frustum
