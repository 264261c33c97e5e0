// Which side of a plane a pair's eye is on, from the pair alone (an eye at
// infinity included), with the tolerance mirror() uses: the eye is column
// 2 of M^-1 up to sign, and with c' = M^-T c it is on c's positive side
// exactly when (z_f - z_n) c'_z < 0.
#pragma once

#include "frustum/detail/errors.hpp"
#include "frustum/detail/tolerances.hpp"
#include "frustum/matrix_pair.hpp"
#include "frustum/plane.hpp"
#include "frustum/queries.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace frustum::detail {

// The rounding floor of a plane's side of the eye, c . M^-1_2 (clip-space
// c'_z): 64 eps sum_i |c_i| |M^-1_2,i|, the dot product's own error bound
// term by term. (|c| |M^-1_2| overstates it by up to the eye's distance
// from the origin times the plane's: a camera 5 km from the origin, 1.4 m
// above a floor mirror, was refused as "passing through the eye".)
template <class T>
T eye_side_floor(const Vec4<T>& plane, const Vec4<T>& eye_column) {
    return rounding_floor<T>() * glm::dot(glm::abs(plane), glm::abs(eye_column));
}

// Empty when the eye is strictly on the unit plane's positive side; else
// the error "frustum::<function>(): <in_plane or behind>, got <plane_name>=(..) eye_distance=..".
template <class T>
std::optional<Error> eye_in_front(const MatrixPair<T>& pair, const Plane<T>& unit_plane, const char* function,
                                  const char* plane_name, const char* in_plane, const char* behind) {
    const T eye_side = -clip_z_span<T>(pair.depth()) * glm::dot(unit_plane.abcd, pair.inverse()[2]);
    const T floor = eye_side_floor(unit_plane.abcd, pair.inverse()[2]);
    if (eye_side > floor) {
        return std::nullopt;
    }
    const Vec4<T> eye = to_point(pair.inverse()[2], infinity_tolerance<T>());
    const std::string where = eye.w == T(1) ? " eye_distance=" + number(unit_plane.distance(Vec3<T>(eye))) : "";
    return error_text(function, std::abs(eye_side) <= floor ? in_plane : behind,
                      std::string(plane_name) + "=" + vector_text(unit_plane.abcd) + where);
}

} // namespace frustum::detail
