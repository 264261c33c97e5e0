// Frustum culling on the matrix pair's planes (§3.1), and the separate
// culling frustum a mirror or portal pass needs (docs/errata.md, erratum 8).
#pragma once

#include "frustum/crop.hpp"
#include "frustum/matrix_pair.hpp"
#include "frustum/portal.hpp"
#include "frustum/queries.hpp"
#include "frustum/result.hpp"

namespace frustum {

enum class Containment { Outside, Intersecting, Inside };

// "outside", "intersect", "inside" (the frustum-vectors words).
constexpr const char* to_string(Containment c) {
    return c == Containment::Outside ? "outside" : c == Containment::Inside ? "inside" : "intersect";
}

// Axis-aligned box in world space, min <= max componentwise.
template <class T>
struct Aabb {
    Vec3<T> min{0}, max{0};
};

template <class T>
struct Sphere {
    Vec3<T> center{0};
    T radius = 0;
};

// The standard plane test, each plane on its own (the far plane only when
// present). Box: Outside when its corner farthest along a plane's normal
// (the "p-vertex") is on that plane's negative side, i.e. all eight
// corners are; Inside when the nearest corner (the "n-vertex") is on the
// non-negative side of every plane; else Intersecting. Planes from
// planes() or raw_planes() (only signs are used).
//
// Conservative: a box outside the frustum but near one of its edges or
// corners, poking past two planes without being wholly behind either one,
// is reported Intersecting (tests/math/culling_test.cpp pins one). It never
// reports Outside for a box that touches the frustum.
template <class T>
Containment classify(const FrustumPlanes<T>& planes, const Aabb<T>& box);

// Sphere: Outside when its centre is more than `radius` behind a plane,
// Inside when at least `radius` in front of every plane. The planes must be
// normalized (planes(), not raw_planes()). Same conservative corner case.
template <class T>
Containment classify(const FrustumPlanes<T>& planes, const Sphere<T>& sphere);

// The frustum to cull a mirror or portal pass with, and the pair it comes
// from. The render frustum of such a pass is obliquely clipped, and the
// oblique clip tilts its far plane through one far corner (eq. 20-22): the
// tilted far plane lies beyond the original far distance everywhere else,
// so culling with it keeps objects the camera's far distance excludes (and
// the unclipped reflected frustum keeps everything behind the mirror).
// The culling frustum instead has
//   - the side planes of `pair`: the reflected (or portalled) camera,
//     cropped to the pass's screen rectangle, NOT clipped;
//   - the mirror (exit) plane as near plane, positive on the visible side;
//   - the far plane of `pair`: the camera's own far plane carried by the
//     reflection or the portal, at the original distance (absent when the
//     camera's far plane is infinite).
// Six planes like these are in general NOT the planes of any projective
// frustum (near and far would have to meet on the line where the side
// planes meet), which is why the oblique clip must tilt the far plane and
// why this is a plane set beside a pair, not a pair.
template <class T>
struct CullingFrustum {
    MatrixPair<T> pair;      // crop(reflect(camera, plane), rect) or crop(M T, rect); analytic inverse
    FrustumPlanes<T> planes; // normalized, inward-positive; near = the mirror or exit plane
};

// Mirror pass: the camera's eye must be on the plane's positive (front)
// side, not in it. `rect` is the pass's screen rectangle (screen_rect()).
template <class T>
Result<CullingFrustum<T>> culling_pair(const MatrixPair<T>& camera, const Plane<T>& mirror_plane,
                                       const CropRect<T>& rect);

// Portal pass: as portal(camera, entry, exit) without the oblique clip;
// the eye must be on the entry's front side.
template <class T>
Result<CullingFrustum<T>> culling_pair(const MatrixPair<T>& camera, const Frame<T>& entry, const Frame<T>& exit,
                                       const CropRect<T>& rect);

} // namespace frustum
