// Rigid transforms (rotation + translation) and the planes they carry.
// RigidTransform<T> itself lives in matrix_pair.hpp (it is a view matrix);
// its inverse and composition are exact here: nothing is inverted
// numerically, the stored inverse is just swapped or multiplied.
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/plane.hpp"
#include "frustum/result.hpp"

namespace frustum {

// The inverse transform: matrix and inverse swapped (exact).
template <class T>
RigidTransform<T> inverse(const RigidTransform<T>& rigid) {
    RigidTransform<T> out;
    out.matrix = rigid.inverse;
    out.inverse = rigid.matrix;
    return out;
}

// `first`, then `second`: matrix = second.matrix * first.matrix,
// inverse = first.inverse * second.inverse.
template <class T>
RigidTransform<T> then(const RigidTransform<T>& first, const RigidTransform<T>& second) {
    RigidTransform<T> out;
    out.matrix = second.matrix * first.matrix;
    out.inverse = first.inverse * second.inverse;
    return out;
}

// The same composition written as the product of matrices: (a * b) p = a (b p).
template <class T>
RigidTransform<T> operator*(const RigidTransform<T>& a, const RigidTransform<T>& b) {
    return then(b, a);
}

// A frame: an origin and two unit, orthogonal axes x (right) and y (up);
// its normal is n = x × y, its front is the side n points to.
template <class T>
struct Frame {
    Vec3<T> origin{0};
    Vec3<T> x{1, 0, 0};
    Vec3<T> y{0, 1, 0};

    Vec3<T> normal() const { return glm::cross(x, y); }
};

// |x| and |y| must be 1 and x . y 0, each within this (absolute) tolerance.
template <class T>
constexpr T frame_tolerance() {
    return T(1e-6);
}

// F: frame-local coordinates to world, columns (x, 0), (y, 0), (n, 0),
// (origin, 1); F^-1 = [F_R^T | -F_R^T origin]. Errors (function is the
// caller's name for the message, `what` names the frame, e.g. "entry"):
// non-finite values, axes not unit length or not orthogonal within
// frame_tolerance().
template <class T>
Result<RigidTransform<T>> frame_to_world(const Frame<T>& frame, const char* function, const char* what);

// The plane through `point` with unit normal unit(normal), positive on the
// side the normal points to: (n, -n . point). The normal must be non-zero
// and everything finite.
template <class T>
Result<Plane<T>> plane_from_point_normal(const Vec3<T>& point, const Vec3<T>& normal);

// The plane carried by a transform: if p' = A p then the plane c becomes
// c' = A^-T c, i.e. c'_j = c . (column j of A^-1). A rigid A keeps a unit
// normal unit and the signed distance of every carried point.
template <class T>
Plane<T> transformed(const Plane<T>& plane, const RigidTransform<T>& rigid) {
    const Vec4<T>& c = plane.abcd;
    const Mat4<T>& inv = rigid.inverse;
    return Plane<T>(glm::dot(c, inv[0]), glm::dot(c, inv[1]), glm::dot(c, inv[2]), glm::dot(c, inv[3]));
}

} // namespace frustum
