// Points where three homogeneous planes meet. The 4D "cross product" of three
// row vectors a, b, c is the vector v with a.v = b.v = c.v = 0 (its entries
// are the 3x3 minors). Used to build the inverse of a matrix given by its
// rows (planes): column j of M^-1 is the point where every row but j
// vanishes, scaled so that row j gives 1 (the key points of §3.2, read
// backwards).
#pragma once

#include "frustum/detail/tolerances.hpp"
#include "frustum/types.hpp"

namespace frustum::detail {

template <class T>
Vec4<T> cross4(const Vec4<T>& a, const Vec4<T>& b, const Vec4<T>& c) {
    // 2x2 minors of rows a, b
    const T xy = a.x * b.y - a.y * b.x;
    const T xz = a.x * b.z - a.z * b.x;
    const T xw = a.x * b.w - a.w * b.x;
    const T yz = a.y * b.z - a.z * b.y;
    const T yw = a.y * b.w - a.w * b.y;
    const T zw = a.z * b.w - a.w * b.z;
    return Vec4<T>(c.y * zw - c.z * yw + c.w * yz,
                   -(c.x * zw - c.z * xw + c.w * xz),
                   c.x * yw - c.y * xw + c.w * xy,
                   -(c.x * yz - c.y * xz + c.z * xy));
}

} // namespace frustum::detail

#include <cmath>
#include <limits>
#include <optional>

namespace frustum::detail {

// The inverse of a matrix given by its rows (planes): column j is the point
// where the three other rows vanish, scaled so that row j gives 1. Empty
// when a row is (nearly) dependent on the others: |sin| of the angle between
// row j and that point below 16 eps.
template <class T>
std::optional<Mat4<T>> inverse_from_rows(const Mat4<T>& m) {
    const Vec4<T> rows[4] = {row(m, 0), row(m, 1), row(m, 2), row(m, 3)};
    Mat4<T> inv;
    for (int j = 0; j < 4; ++j) {
        const Vec4<T>& a = rows[j == 0 ? 1 : 0];
        const Vec4<T>& b = rows[j <= 1 ? 2 : 1];
        const Vec4<T>& c = rows[j <= 2 ? 3 : 2];
        const Vec4<T> point = cross4(a, b, c);
        const T scale = glm::dot(rows[j], point);
        const T reference = glm::length(rows[j]) * glm::length(point);
        if (!(std::abs(scale) > dependent_rows_floor<T>() * reference)) {
            return std::nullopt;
        }
        inv[j] = point / scale;
    }
    return inv;
}

} // namespace frustum::detail
