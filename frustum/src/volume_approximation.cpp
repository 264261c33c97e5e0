#include "frustum/volume_approximation.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/tolerances.hpp"
#include "frustum/detail/finite.hpp"
#include "frustum/reflect.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace frustum {

template <class T>
T volume_objective(const VolumeTarget<T>& target, const Vec3<T>& origin, Vec3<T>* gradient) {
    T sum = T(0);
    Vec3<T> grad(T(0));
    for (int i = 0; i < 4; ++i) {
        const Vec3<T>& xi = target.near_points[i];
        const Vec3<T>& xj = target.near_points[(i + 1) % 4];
        const Vec3<T>& t = target.side_normals[i];
        const Vec3<T> n = glm::cross(xi - origin, xj - origin); // n_i = OX_i x OX_i+1
        const T n2 = glm::dot(n, n);
        if (!(n2 > T(0))) {
            continue; // O on the edge line: F_i undefined, contributes nothing
        }
        const T nt = glm::dot(n, t);
        sum += nt * nt / n2; // F_i^2 = cos^2 alpha_i
        const Vec3<T> d = xi - xj;
        // grad F_i^2 = 2 (n.t)(d x t)/|n|^2 - 2 (n.t)^2 (d x n)/|n|^4 (erratum 6)
        grad += (T(2) * nt / n2) * glm::cross(d, t) - (T(2) * nt * nt / (n2 * n2)) * glm::cross(d, n);
    }
    if (gradient) {
        *gradient = grad;
    }
    return sum;
}

namespace {

// Where three planes meet, if they do (Cramer's rule).
template <class T>
bool intersect3(const Plane<T>& a, const Plane<T>& b, const Plane<T>& c, Vec3<T>& out) {
    const Mat3<T> rows_t(a.normal(), b.normal(), c.normal()); // columns = normals
    const T det = glm::determinant(rows_t);
    if (!(std::abs(det) > detail::corner_determinant_floor<T>())) {
        return false;
    }
    // Solve n_k . x = -d_k: x = (-(d_a) (b x c) - d_b (c x a) - d_c (a x b)) / det
    out = (-a.offset() * glm::cross(b.normal(), c.normal()) - b.offset() * glm::cross(c.normal(), a.normal()) -
           c.offset() * glm::cross(a.normal(), b.normal())) /
          det;
    return detail::finite3(out);
}


// The target must be finite, its side normals non-zero, its near plane a
// plane, and X0..X3 a quadrilateral with no zero-length side.
template <class T>
Status check_target(const VolumeTarget<T>& target) {
    for (int i = 0; i < 4; ++i) {
        const Vec3<T>& x = target.near_points[i];
        const Vec3<T>& t = target.side_normals[i];
        if (!detail::finite3(x) || !detail::finite3(t) || !(glm::length(t) > T(0))) {
            return detail::error_text("fit_volume", "near points and side normals must be finite, normals non-zero",
                                      "X" + std::to_string(i) + "=" + detail::vector_text(x) + " t" +
                                          std::to_string(i) + "=" + detail::vector_text(t));
        }
        const Vec3<T> side = target.near_points[(i + 1) % 4] - x;
        if (!(glm::length(side) > T(0))) {
            return detail::error_text("fit_volume", "consecutive near points must differ",
                                      "X" + std::to_string(i) + "=" + detail::vector_text(x));
        }
    }
    const Vec3<T> diagonal_cross = glm::cross(target.near_points[2] - target.near_points[0],
                                              target.near_points[3] - target.near_points[1]);
    if (!(glm::length(diagonal_cross) > T(0))) {
        return detail::error_text("fit_volume", "near points must span a quadrilateral (they are collinear)", "");
    }
    if (const Status s = check_plane(target.near, "fit_volume"); !s) {
        return s;
    }
    return {};
}

} // namespace

template <class T>
Result<VolumeFit<T>> fit_volume(const VolumeTarget<T>& target, T far_distance_m, DepthRange depth,
                                int max_iterations, T tolerance) {
    if (!(far_distance_m > T(0)) || !std::isfinite(far_distance_m)) {
        return detail::error<T>("fit_volume", "far distance must be > 0 and finite", {{"far", far_distance_m}});
    }
    if (const Status s = check_target(target); !s) {
        return s.take_error();
    }
    const Plane<T> near = target.near.normalized();
    Vec3<T> centroid(T(0));
    for (const Vec3<T>& x : target.near_points) {
        centroid += x / T(4);
    }
    // Side planes of the target, through their edge: t_i . (p - X_i) = 0.
    Plane<T> sides[4];
    for (int i = 0; i < 4; ++i) {
        sides[i] = Plane<T>(Vec4<T>(target.side_normals[i], -glm::dot(target.side_normals[i], target.near_points[i])));
    }
    // The paper's start: intersect(T0, T1, T2); it must lie behind the near plane.
    Vec3<T> origin;
    if (!intersect3(sides[0], sides[1], sides[2], origin) || !(near.distance(origin) < T(0))) {
        const T size = glm::length(target.near_points[2] - target.near_points[0]);
        origin = centroid - near.normal() * size;
    }

    Vec3<T> gradient;
    T value = volume_objective(target, origin, &gradient);
    int iterations = 0;
    T step = T(1);
    for (; iterations < max_iterations; ++iterations) {
        // Backtracking (Armijo) line search along the gradient.
        const T g2 = glm::dot(gradient, gradient);
        if (!(g2 > T(0))) {
            break;
        }
        bool improved = false;
        for (int halvings = 0; halvings < 60; ++halvings) {
            const Vec3<T> candidate = origin + step * gradient;
            Vec3<T> candidate_gradient;
            const T candidate_value = volume_objective(target, candidate, &candidate_gradient);
            if (near.distance(candidate) < T(0) && candidate_value >= value + detail::sufficient_increase<T>() * step * g2) {
                const T gain = candidate_value - value;
                origin = candidate;
                value = candidate_value;
                gradient = candidate_gradient;
                step *= T(2);
                improved = gain > tolerance;
                break;
            }
            step /= T(2);
        }
        if (!improved) {
            break;
        }
    }

    // The frustum through O and X0..X3 (§4 from planes).
    const auto& x = target.near_points;
    // Each side plane through the origin and two near points, positive on the
    // centroid's side; a zero normal (origin on the line through the two
    // points) stays zero and is refused by from_planes.
    const auto side = [&](const Vec3<T>& a, const Vec3<T>& b) { return Plane<T>::through(origin, a, b).facing(centroid); };
    const SidePlanes<T> planes{side(x[3], x[0]), side(x[1], x[2]), side(x[2], x[3]), side(x[0], x[1]), near};
    // Far plane: the nearest that keeps each edge from O through X_i inside
    // up to far_distance_m beyond X_i (one far point on the axis tilts it into
    // the volume when the patch is far from a parallelogram).
    std::vector<Vec3<T>> far_points;
    for (const Vec3<T>& corner : x) {
        const T length = glm::length(corner - origin);
        if (!(length > T(0))) {
            return detail::error_text("fit_volume", "the fitted origin lies on a near point",
                                      detail::vector_text(origin));
        }
        far_points.push_back(corner + (corner - origin) * (far_distance_m / length));
    }
    auto pair = from_planes(planes, far_points, depth);
    if (!pair) {
        return pair.take_error_in("frustum::fit_volume()");
    }
    return VolumeFit<T>{origin, value, iterations, std::move(pair).value()};
}

#define FRUSTUM_INSTANTIATE(T)                                                                     \
    template T volume_objective(const VolumeTarget<T>&, const Vec3<T>&, Vec3<T>*);                 \
    template Result<VolumeFit<T>> fit_volume(const VolumeTarget<T>&, T, DepthRange, int, T);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
