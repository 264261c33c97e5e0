// Plane<T>: a x + b y + c z + d = 0, stored as (a, b, c, d).
//
// Convention, tested in tests/math: a frustum's planes point INWARD, i.e.
// distance(p) >= 0 for every point p inside (the centre D is at positive
// distance from all six). Normalized planes have |(a, b, c)| = 1.
#pragma once

#include "frustum/types.hpp"

#include <algorithm>
#include <cmath>

namespace frustum {

template <class T>
struct Plane {
    Vec4<T> abcd{0};

    Plane() = default;
    explicit Plane(const Vec4<T>& coefficients) : abcd(coefficients) {}
    Plane(T a, T b, T c, T d) : abcd(a, b, c, d) {}

    // The plane with this normal (any length) through `point`, unchecked;
    // for user input use plane_from_point_normal (rigid.hpp: checked, unit).
    static Plane at(const Vec3<T>& normal, const Vec3<T>& point) {
        return Plane(Vec4<T>(normal, -glm::dot(normal, point)));
    }
    // The plane through three points, normal (b - a) x (c - a), not
    // normalized: positive on the side from which a, b, c turn
    // counter-clockwise. Zero normal when the points are collinear.
    static Plane through(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
        return at(glm::cross(b - a, c - a), a);
    }

    Vec3<T> normal() const { return Vec3<T>(abcd); }
    T offset() const { return abcd.w; }

    // Signed value at a Euclidean point (a distance when normalized).
    T distance(const Vec3<T>& p) const { return glm::dot(normal(), p) + abcd.w; }
    // Value at a homogeneous point (x, y, z, w).
    T evaluate(const Vec4<T>& p) const { return glm::dot(abcd, p); }

    // |normal| = 1, computed without overflow or underflow (the coefficients
    // are first scaled by their largest magnitude). A plane at infinity (zero
    // normal, d != 0) comes back as (0, 0, 0, sign d); the zero plane stays zero.
    Plane normalized() const {
        const T largest = std::max(std::max(std::abs(abcd.x), std::abs(abcd.y)),
                                   std::max(std::abs(abcd.z), std::abs(abcd.w)));
        if (!(largest > T(0))) {
            return *this;
        }
        const Vec4<T> scaled = abcd / largest;
        const T length = glm::length(Vec3<T>(scaled));
        if (!(length > T(0))) {
            return Plane(Vec4<T>(T(0), T(0), T(0), scaled.w > T(0) ? T(1) : T(-1)));
        }
        return Plane(scaled / length);
    }
    // The same plane, other side positive.
    Plane flipped() const { return Plane(-abcd); }
    // The same plane oriented so that `inside` is on its non-negative side:
    // this plane when distance(inside) >= 0, else flipped().
    Plane facing(const Vec3<T>& inside) const { return distance(inside) >= T(0) ? *this : flipped(); }

    // True when the normal is (relatively) zero: no plane, e.g. the far
    // plane of an infinite frustum (docs/errata.md erratum 9).
    bool is_degenerate(T relative_tolerance) const {
        const T n = glm::length(normal());
        return !(n > relative_tolerance * std::abs(abcd.w)) || !std::isfinite(n);
    }
};

} // namespace frustum
