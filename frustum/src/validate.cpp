#include "frustum/validate.hpp"

#include "frustum/detail/tolerances.hpp"

#include "frustum/queries.hpp"

#include <cmath>

namespace frustum {

std::string Validation::reason() const {
    if (!near_quad_finite) return "near corners are not all finite points";
    if (!near_quad_convex) return "near face is not a convex quadrilateral";
    if (!eye_behind_near) return "eye is not on the near plane's negative side";
    if (!far_corners_beyond) return "far corners are not all in front of the eye beyond the near plane";
    return "";
}

template <class T>
Validation validate(const MatrixPair<T>& pair) {
    Validation result;
    const KeyPoints<T> points = key_points(pair);
    const T tolerance = infinity_tolerance<T>();

    Vec3<T> quad[4];
    result.near_quad_finite = true;
    for (int i = 0; i < 4; ++i) {
        const Vec4<T> p = to_point(points.corners[i], tolerance);
        if (p.w != T(1)) {
            result.near_quad_finite = false;
            return result;
        }
        quad[i] = Vec3<T>(p);
    }

    // Convexity: the turn at every vertex points the same way (pairwise
    // cross products of consecutive sides, §5.5), and none is degenerate.
    Vec3<T> turns[4];
    Vec3<T> turn_sum(0);
    T perimeter = T(0);
    for (int i = 0; i < 4; ++i) {
        const Vec3<T> side_in = quad[(i + 1) % 4] - quad[i];
        const Vec3<T> side_out = quad[(i + 2) % 4] - quad[(i + 1) % 4];
        turns[i] = glm::cross(side_in, side_out);
        turn_sum += turns[i];
        perimeter += glm::length(side_in);
    }
    result.near_quad_convex = true;
    const T area_floor = detail::rounding_floor<T>() * perimeter * perimeter;
    for (const Vec3<T>& turn : turns) {
        if (!(glm::dot(turn, turn_sum) > area_floor * glm::length(turn_sum))) {
            result.near_quad_convex = false;
        }
    }

    // Separation: eye strictly behind the near plane, far corners beyond it
    // and in front of the eye (w >= 0: a far corner at infinity counts).
    const Vec4<T> near = raw_planes(pair).near.abcd;
    const Vec4<T> eye = to_point(points.eye, tolerance);
    if (eye.w == T(1)) {
        result.eye_behind_near = glm::dot(near, eye) < T(0);
    } else {
        // Orthographic: the eye is at infinity; the near plane must not be
        // parallel to the projection direction.
        result.eye_behind_near = std::abs(glm::dot(Vec3<T>(near), Vec3<T>(eye))) > tolerance * glm::length(Vec3<T>(near));
    }
    result.far_corners_beyond = true;
    for (int i = 4; i < 8; ++i) {
        const Vec4<T>& c = points.corners[i];
        const T scale = glm::length(Vec3<T>(c));
        if (!(c.w >= -tolerance * scale) || !(glm::dot(near, c) > T(0))) {
            result.far_corners_beyond = false;
        }
    }
    return result;
}

template Validation validate(const MatrixPair<float>&);
template Validation validate(const MatrixPair<double>&);

} // namespace frustum
