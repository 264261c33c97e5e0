#include "frustum/volume_approximation.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/tolerances.hpp"
#include "frustum/detail/finite.hpp"
#include "frustum/reflect.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

// F(O), its gradient and its Hessian. n_i(O) = OX_i x OX_i+1 = X_i x X_i+1 -
// d x O is affine in O (d = X_i - X_i+1), so with a = n.t and b = |n|^2:
//   grad a = d x t,  grad b = 2 d x n,  hess a = 0,  hess b = 2 (|d|^2 I - d d^T),
//   hess (a^2 / b) = 2 ga ga^T / b - 2 a (ga gb^T + gb ga^T) / b^2
//                    - a^2 hess b / b^2 + 2 a^2 gb gb^T / b^3.
template <class T>
T objective_derivatives(const VolumeTarget<T>& target, const Vec3<T>& origin, Vec3<T>& gradient, Mat3<T>& hessian) {
    T sum = T(0);
    gradient = Vec3<T>(T(0));
    hessian = Mat3<T>(T(0));
    for (int i = 0; i < 4; ++i) {
        const Vec3<T>& xi = target.near_points[i];
        const Vec3<T>& xj = target.near_points[(i + 1) % 4];
        const Vec3<T>& t = target.side_normals[i];
        const Vec3<T> n = glm::cross(xi - origin, xj - origin);
        const T b = glm::dot(n, n);
        if (!(b > T(0))) {
            continue; // as volume_objective
        }
        const T a = glm::dot(n, t);
        const Vec3<T> d = xi - xj;
        const Vec3<T> ga = glm::cross(d, t);
        const Vec3<T> gb = T(2) * glm::cross(d, n);
        const T inv_b = T(1) / b;
        sum += a * a * inv_b;
        gradient += (T(2) * a * inv_b) * ga - (a * a * inv_b * inv_b) * gb;
        const Mat3<T> hess_b = T(2) * (glm::dot(d, d) * Mat3<T>(T(1)) - glm::outerProduct(d, d));
        const Mat3<T> cross_terms = glm::outerProduct(ga, gb) + glm::outerProduct(gb, ga);
        hessian += (T(2) * inv_b) * glm::outerProduct(ga, ga) - (T(2) * a * inv_b * inv_b) * cross_terms -
                   (a * a * inv_b * inv_b) * hess_b + (T(2) * a * a * inv_b * inv_b * inv_b) * glm::outerProduct(gb, gb);
    }
    return sum;
}

// Solves A x = g for a symmetric positive definite 3x3 A (Cholesky); false
// when A is not positive definite.
template <class T>
bool solve_positive_definite(const Mat3<T>& A, const Vec3<T>& g, Vec3<T>& x) {
    const T l00s = A[0][0];
    if (!(l00s > T(0))) return false;
    const T l00 = std::sqrt(l00s);
    const T l10 = A[0][1] / l00, l20 = A[0][2] / l00;
    const T l11s = A[1][1] - l10 * l10;
    if (!(l11s > T(0))) return false;
    const T l11 = std::sqrt(l11s);
    const T l21 = (A[1][2] - l20 * l10) / l11;
    const T l22s = A[2][2] - l20 * l20 - l21 * l21;
    if (!(l22s > T(0))) return false;
    const T l22 = std::sqrt(l22s);
    // L y = g, then L^T x = y.
    const T y0 = g.x / l00, y1 = (g.y - l10 * y0) / l11, y2 = (g.z - l20 * y0 - l21 * y1) / l22;
    x.z = y2 / l22;
    x.y = (y1 - l21 * x.z) / l11;
    x.x = (y0 - l10 * x.y - l20 * x.z) / l00;
    return detail::finite3(x);
}

// The smallest eigenvalue of a symmetric 3x3 A (the closed form of the
// characteristic cubic's roots, Smith 1961: A = q I + p B, the roots of
// det(B - b I) = 0 are 2 cos(phi + 2 k pi / 3), phi = acos(det(B) / 2) / 3).
template <class T>
T smallest_eigenvalue(const Mat3<T>& A) {
    const T off = A[0][1] * A[0][1] + A[0][2] * A[0][2] + A[1][2] * A[1][2];
    const T q = (A[0][0] + A[1][1] + A[2][2]) / T(3);
    if (!(off > T(0))) {
        return std::min(std::min(A[0][0], A[1][1]), A[2][2]);
    }
    const T p = std::sqrt(((A[0][0] - q) * (A[0][0] - q) + (A[1][1] - q) * (A[1][1] - q) +
                           (A[2][2] - q) * (A[2][2] - q) + T(2) * off) /
                          T(6));
    const Mat3<T> B = (A - q * Mat3<T>(T(1))) / p;
    const T half_det = std::clamp(glm::determinant(B) / T(2), T(-1), T(1));
    const T phi = std::acos(half_det) / T(3);
    return q + T(2) * p * std::cos(phi + T(2.0943951023931954923)); // + 2 pi / 3: the smallest root
}

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
                                int max_iterations, T tolerance, const std::optional<Vec3<T>>& start) {
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

    // A warm start (the neighbouring patch's origin, the previous frame's)
    // when it is behind the near plane and no worse than the paper's.
    if (start && detail::finite3(*start) && near.distance(*start) < T(0) &&
        volume_objective(target, *start) >= volume_objective(target, origin)) {
        origin = *start;
    }

    // Newton's method on F with its analytic Hessian, damped (Levenberg-
    // Marquardt: (mu I - H) step = grad). F is flat along the patch's axis
    // (a near-zero eigenvalue of H, of either sign), where a plain Newton
    // step is unbounded. Where -H + mu I is not positive definite, mu is
    // raised past -H's smallest eigenvalue at once (closed form; no point is
    // tried). A tried step that does not gain, or leaves the near plane's
    // back, raises mu tenfold; a step that gains lowers it a hundredfold.
    // Stops when a step gains less than `tolerance`. Every tried step (an
    // evaluation of F and its derivatives at a new point) counts as an
    // iteration.
    Vec3<T> gradient;
    Mat3<T> hessian;
    T value = objective_derivatives(target, origin, gradient, hessian);
    int iterations = 0;
    const T scale = std::max(std::abs(hessian[0][0]) + std::abs(hessian[1][1]) + std::abs(hessian[2][2]),
                             std::numeric_limits<T>::min());
    T damping = T(0);
    int rejected = 0;
    int shifts = 0;
    while (iterations < max_iterations) {
        if (!(glm::dot(gradient, gradient) > T(0))) {
            break;
        }
        Mat3<T> system = -hessian;
        for (int k = 0; k < 3; ++k) {
            system[k][k] += damping * scale;
        }
        Vec3<T> step;
        if (!solve_positive_definite(system, gradient, step)) {
            // Twice the shift that makes it semi-definite (in units of
            // `scale`), and at least tenfold the damping tried (1e-2 at first).
            const T needed = -smallest_eigenvalue(Mat3<T>(-hessian)) / scale;
            const T next = std::max(T(2) * needed, damping > T(0) ? damping * T(10) : T(1e-2));
            if (!(next > damping) || !std::isfinite(next) || ++shifts > 60) {
                break; // no damping makes a system to solve (NaN in H)
            }
            damping = next;
            continue;
        }
        // The gain the quadratic model predicts, g . step / 2 (exact for a
        // pure Newton step, an overestimate when damped): below a thousandth
        // of `tolerance` means converged (the step after would gain less than
        // `tolerance` by far), and there a step would only round F down.
        if (!(glm::dot(gradient, step) > T(2e-3) * tolerance)) {
            break;
        }
        ++iterations;
        const Vec3<T> candidate = origin + step;
        Vec3<T> candidate_gradient;
        Mat3<T> candidate_hessian;
        const T candidate_value = objective_derivatives(target, candidate, candidate_gradient, candidate_hessian);
        if (near.distance(candidate) < T(0) && candidate_value >= value) {
            const T gain = candidate_value - value;
            origin = candidate;
            value = candidate_value;
            gradient = candidate_gradient;
            hessian = candidate_hessian;
            damping *= T(0.01);
            rejected = 0;
            if (!(gain > tolerance)) {
                break; // converged
            }
        } else {
            damping = damping > T(0) ? damping * T(10) : T(1e-2);
            if (++rejected > 40) {
                break; // no step gains any more: F is at its maximum to rounding
            }
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
    template Result<VolumeFit<T>> fit_volume(const VolumeTarget<T>&, T, DepthRange, int, T,                 \
                                             const std::optional<Vec3<T>>&);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
