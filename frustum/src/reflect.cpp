#include "frustum/reflect.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/pair_factory.hpp"

#include <cmath>

namespace frustum {

namespace {

// One test catches NaN and infinity in any coefficient (inf - inf and
// anything + NaN are not finite) and a zero or overflowing normal.
template <class T>
bool usable(const Plane<T>& plane, T length_squared) {
    return std::isfinite(length_squared + plane.abcd.w) && length_squared > T(0);
}

template <class T>
Error plane_error(const Plane<T>& plane, const char* function) {
    const Vec4<T>& c = plane.abcd;
    const bool finite = std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w);
    return detail::error_text(function, finite ? "plane normal must be non-zero and finite" : "plane must be finite",
                              detail::vector_text(c));
}

} // namespace

template <class T>
Result<Plane<T>> checked_unit_plane(const Plane<T>& plane, const char* function) {
    const T length_squared = glm::dot(plane.normal(), plane.normal());
    if (usable(plane, length_squared)) {
        return Plane<T>(plane.abcd * (T(1) / std::sqrt(length_squared)));
    }
    return plane_error(plane, function);
}

template <class T>
Status check_plane(const Plane<T>& plane, const char* function) {
    if (usable(plane, glm::dot(plane.normal(), plane.normal()))) {
        return {};
    }
    return plane_error(plane, function);
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
    const auto unit = checked_unit_plane(plane, "reflect");
    if (!unit) {
        return Error{unit.error()};
    }
    const Vec4<T> c = unit->abcd;
    const Vec4<T> n(unit->normal(), T(0));
    // M' = M R = M - 2 (M n) c^T: column j of M' is M_j - 2 c_j (M n).
    const Vec4<T> m_n = pair.matrix() * n;
    Mat4<T> m = pair.matrix();
    for (int j = 0; j < 4; ++j) {
        m[j] -= (T(2) * c[j]) * m_n;
    }
    // inv' = R inv = inv - 2 n (c^T inv): column j gets -2 (c . inv_j) n.
    Mat4<T> inv = pair.inverse();
    for (int j = 0; j < 4; ++j) {
        inv[j] -= (T(2) * glm::dot(c, pair.inverse()[j])) * n;
    }
    return detail::PairFactory::keep_sign(m, inv, pair.depth(), !pair.flips_winding());
}

#define FRUSTUM_INSTANTIATE(T)                                                    \
    template Result<Plane<T>> checked_unit_plane(const Plane<T>&, const char*);   \
    template Status check_plane(const Plane<T>&, const char*);                    \
    template Mat4<T> reflection_matrix(const Plane<T>&);                          \
    template Result<MatrixPair<T>> reflect(const MatrixPair<T>&, const Plane<T>&);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
