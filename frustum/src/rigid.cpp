#include "frustum/rigid.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/finite.hpp"

#include <cmath>

namespace frustum {

template <class T>
Result<RigidTransform<T>> frame_to_world(const Frame<T>& frame, const char* function, const char* what) {
    const std::string name(what);
    if (!detail::finite3(frame.origin) || !detail::finite3(frame.x) || !detail::finite3(frame.y)) {
        return detail::error_text(function, name + " frame must be finite",
                                  "origin=" + detail::vector_text(frame.origin) + " x=" + detail::vector_text(frame.x) +
                                      " y=" + detail::vector_text(frame.y));
    }
    const T tolerance = frame_tolerance<T>();
    const T x_length = glm::length(frame.x), y_length = glm::length(frame.y);
    const T x_dot_y = glm::dot(frame.x, frame.y);
    if (!(std::abs(x_length - T(1)) <= tolerance) || !(std::abs(y_length - T(1)) <= tolerance) ||
        !(std::abs(x_dot_y) <= tolerance)) {
        return detail::error<T>(function,
                                name + " frame axes x and y must be unit length and orthogonal (each within 1e-6)",
                                {{"|x|", x_length}, {"|y|", y_length}, {"x.y", x_dot_y}});
    }
    const Vec3<T> n = frame.normal();
    // Columns x, y, n: local -> world rotation; translation = origin.
    Mat3<T> rotation;
    rotation[0] = frame.x;
    rotation[1] = frame.y;
    rotation[2] = n;
    return RigidTransform<T>::from_rotation_translation(rotation, frame.origin);
}

template <class T>
Result<Plane<T>> plane_from_point_normal(const Vec3<T>& point, const Vec3<T>& normal) {
    if (!detail::finite3(point) || !detail::finite3(normal)) {
        return detail::error_text("plane_from_point_normal", "point and normal must be finite",
                                  "point=" + detail::vector_text(point) + " normal=" + detail::vector_text(normal));
    }
    // Scale first so that a tiny or huge normal neither underflows nor overflows.
    const T largest = std::max(std::max(std::abs(normal.x), std::abs(normal.y)), std::abs(normal.z));
    if (!(largest > T(0))) {
        return detail::error_text("plane_from_point_normal", "normal must be non-zero",
                                  "normal=" + detail::vector_text(normal));
    }
    const Vec3<T> scaled = normal / largest;
    const Vec3<T> unit = scaled / glm::length(scaled);
    return Plane<T>::at(unit, point);
}

#define FRUSTUM_INSTANTIATE(T)                                                                    \
    template Result<RigidTransform<T>> frame_to_world(const Frame<T>&, const char*, const char*); \
    template Result<Plane<T>> plane_from_point_normal(const Vec3<T>&, const Vec3<T>&);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
