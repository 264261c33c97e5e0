#include "frustum/culling.hpp"

#include "frustum/detail/eye_side.hpp"
#include "frustum/detail/portal_preamble.hpp"
#include "frustum/projection.hpp"
#include "frustum/reflect.hpp"

#include <array>
#include <cmath>

namespace frustum {

namespace {

// The loop of both tests: side(plane) says where the volume is against one
// plane (Outside: wholly behind it, Intersecting: across it, Inside: in
// front); absent planes (an infinite far) are skipped.
template <class T, class Side>
Containment classify_by_planes(const FrustumPlanes<T>& planes, const Side& side) {
    bool inside = true;
    for (const auto& plane : planes.as_array()) {
        if (!plane) {
            continue;
        }
        const Containment against = side(*plane);
        if (against == Containment::Outside) {
            return Containment::Outside;
        }
        inside = inside && against == Containment::Inside;
    }
    return inside ? Containment::Inside : Containment::Intersecting;
}

} // namespace

template <class T>
Containment classify(const FrustumPlanes<T>& planes, const Aabb<T>& box) {
    return classify_by_planes(planes, [&box](const Plane<T>& plane) {
        const Vec3<T> n = plane.normal();
        // p-vertex: the corner farthest along n; n-vertex: the nearest.
        const Vec3<T> p(n.x >= T(0) ? box.max.x : box.min.x, n.y >= T(0) ? box.max.y : box.min.y,
                        n.z >= T(0) ? box.max.z : box.min.z);
        const Vec3<T> q(n.x >= T(0) ? box.min.x : box.max.x, n.y >= T(0) ? box.min.y : box.max.y,
                        n.z >= T(0) ? box.min.z : box.max.z);
        if (plane.distance(p) < T(0)) {
            return Containment::Outside;
        }
        return plane.distance(q) < T(0) ? Containment::Intersecting : Containment::Inside;
    });
}

template <class T>
Containment classify(const FrustumPlanes<T>& planes, const Sphere<T>& sphere) {
    return classify_by_planes(planes, [&sphere](const Plane<T>& plane) {
        const T d = plane.distance(sphere.center);
        if (d < -sphere.radius) {
            return Containment::Outside;
        }
        return d < sphere.radius ? Containment::Intersecting : Containment::Inside;
    });
}

namespace {

template <class T>
Result<CullingFrustum<T>> cropped_with_near(const MatrixPair<T>& carried, const Plane<T>& near_plane,
                                            const CropRect<T>& rect, const char* function) {
    auto cropped = crop(carried, rect);
    if (!cropped) {
        return cropped.take_error_in(std::string("frustum::") + function + "()");
    }
    FrustumPlanes<T> p = planes(*cropped);
    p.near = near_plane.normalized();
    return CullingFrustum<T>{*cropped, p};
}

} // namespace

template <class T>
Result<CullingFrustum<T>> culling_pair(const MatrixPair<T>& camera, const Plane<T>& mirror_plane,
                                       const CropRect<T>& rect) {
    const auto unit = checked_unit_plane(mirror_plane, "culling_pair");
    if (!unit) {
        return unit.take_error();
    }
    if (const auto error = detail::eye_in_front(camera, *unit, "culling_pair", "plane",
                                                "mirror plane must not pass through the eye",
                                                "the eye must be on the mirror plane's positive (front) side")) {
        return *error;
    }
    const auto reflected = reflect(camera, *unit);
    if (!reflected) {
        return reflected.take_error();
    }
    return cropped_with_near(*reflected, *unit, rect, "culling_pair");
}

template <class T>
Result<CullingFrustum<T>> culling_pair(const MatrixPair<T>& camera, const Frame<T>& entry, const Frame<T>& exit,
                                       const CropRect<T>& rect) {
    const auto carried = detail::carried_through_portal(camera, entry, exit, "culling_pair");
    if (!carried) {
        return carried.take_error();
    }
    return cropped_with_near(*carried, frame_plane(exit), rect, "culling_pair");
}

#define FRUSTUM_INSTANTIATE(T)                                                                              \
    template Containment classify(const FrustumPlanes<T>&, const Aabb<T>&);                                 \
    template Containment classify(const FrustumPlanes<T>&, const Sphere<T>&);                               \
    template Result<CullingFrustum<T>> culling_pair(const MatrixPair<T>&, const Plane<T>&, const CropRect<T>&); \
    template Result<CullingFrustum<T>> culling_pair(const MatrixPair<T>&, const Frame<T>&, const Frame<T>&,  \
                                                    const CropRect<T>&);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
