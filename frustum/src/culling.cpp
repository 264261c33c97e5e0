#include "frustum/culling.hpp"

#include "frustum/detail/eye_side.hpp"
#include "frustum/detail/portal_preamble.hpp"
#include "frustum/projection.hpp"
#include "frustum/reflect.hpp"

#include <array>
#include <cmath>

namespace frustum {

template <class T>
Containment classify(const FrustumPlanes<T>& planes, const Aabb<T>& box) {
    bool inside = true;
    for (const auto& plane : planes.as_array()) {
        if (!plane) {
            continue;
        }
        const Vec3<T> n = plane->normal();
        // p-vertex: the corner farthest along n; n-vertex: the nearest.
        const Vec3<T> p(n.x >= T(0) ? box.max.x : box.min.x, n.y >= T(0) ? box.max.y : box.min.y,
                        n.z >= T(0) ? box.max.z : box.min.z);
        const Vec3<T> q(n.x >= T(0) ? box.min.x : box.max.x, n.y >= T(0) ? box.min.y : box.max.y,
                        n.z >= T(0) ? box.min.z : box.max.z);
        if (plane->distance(p) < T(0)) {
            return Containment::Outside;
        }
        if (plane->distance(q) < T(0)) {
            inside = false;
        }
    }
    return inside ? Containment::Inside : Containment::Intersecting;
}

template <class T>
Containment classify(const FrustumPlanes<T>& planes, const Sphere<T>& sphere) {
    bool inside = true;
    for (const auto& plane : planes.as_array()) {
        if (!plane) {
            continue;
        }
        const T d = plane->distance(sphere.center);
        if (d < -sphere.radius) {
            return Containment::Outside;
        }
        if (d < sphere.radius) {
            inside = false;
        }
    }
    return inside ? Containment::Inside : Containment::Intersecting;
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
