#include "frustum/reflect.hpp"

#include "frustum/detail/pair_updates.hpp"

#include <cmath>

namespace frustum {

template <class T>
Result<Plane<T>> checked_unit_plane(const Plane<T>& plane, const char* function) {
    const T length_squared = detail::normal_length_squared(plane.abcd);
    if (detail::plane_usable(plane.abcd, length_squared)) {
        return Plane<T>(plane.abcd * (T(1) / std::sqrt(length_squared)));
    }
    return detail::plane_error(plane.abcd, function);
}

template <class T>
Status check_plane(const Plane<T>& plane, const char* function) {
    if (detail::plane_usable(plane.abcd, detail::normal_length_squared(plane.abcd))) {
        return {};
    }
    return detail::plane_error(plane.abcd, function);
}

template <class T>
Mat4<T> reflection_matrix(const Plane<T>& unit_plane) {
    const Vec3<T> n = unit_plane.normal();
    const T d = unit_plane.offset();
    Mat4<T> r(T(1));
    for (int col = 0; col < 3; ++col) {
        for (int rw = 0; rw < 3; ++rw) {
            r[col][rw] -= T(2) * n[rw] * n[col]; // eq. 16: 1 - 2 c_x^2, -2 c_x c_y, ...
        }
    }
    r[3] = Vec4<T>(T(-2) * d * n, T(1)); // eq. 16 last row: -2 c_w c_xyz
    return r;
}

template <class T>
Result<MatrixPair<T>> reflect(const MatrixPair<T>& pair, const Plane<T>& plane) {
    const T length_squared = detail::normal_length_squared(plane.abcd);
    if (!detail::plane_usable(plane.abcd, length_squared)) {
        return detail::plane_error(plane.abcd, "reflect");
    }
    return detail::reflect_unit(pair, plane.abcd * (T(1) / std::sqrt(length_squared)));
}

#define FRUSTUM_INSTANTIATE(T)                                                    \
    template Result<Plane<T>> checked_unit_plane(const Plane<T>&, const char*);   \
    template Status check_plane(const Plane<T>&, const char*);                    \
    template Mat4<T> reflection_matrix(const Plane<T>&);                          \
    template Result<MatrixPair<T>> reflect(const MatrixPair<T>&, const Plane<T>&);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
