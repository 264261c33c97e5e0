#include "frustum/from_planes.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/tolerances.hpp"
#include "frustum/detail/finite.hpp"
#include "frustum/detail/from_planes_points.hpp"
#include "frustum/detail/pair_factory.hpp"
#include "frustum/detail/plane_intersection.hpp"
#include "frustum/queries.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

namespace frustum {

namespace {

template <class T>
bool finite_plane(const Plane<T>& p) {
    return detail::finite4(p.abcd);
}

// Rows m0, m1, m3 of the matrix (m2 still open) and the eye they meet in.
template <class T>
struct SideRows {
    Vec4<T> m0, m1, m3;
    Plane<T> near; // normalized
};

template <class T>
Result<SideRows<T>> side_rows(const SidePlanes<T>& input, const char* function) {
    const Plane<T>* all[5] = {&input.left, &input.right, &input.bottom, &input.top, &input.near};
    const char* names[5] = {"left", "right", "bottom", "top", "near"};
    Plane<T> unit[5];
    for (int i = 0; i < 5; ++i) {
        if (!finite_plane(*all[i]) || !(glm::length(all[i]->normal()) > T(0))) {
            return detail::error_text(function, std::string(names[i]) + " plane must be finite with a non-zero normal",
                                      detail::vector_text(all[i]->abcd));
        }
        unit[i] = all[i]->normalized();
    }
    const Vec4<T> L = unit[0].abcd, R = unit[1].abcd, B = unit[2].abcd, Tp = unit[3].abcd;

    // eq. 10 in the inward convention: [-R B T] (K_r, K_b, K_t) = L (xyz).
    const Mat3<T> system(-Vec3<T>(R), Vec3<T>(B), Vec3<T>(Tp)); // columns
    const T det = glm::determinant(system);
    if (!(std::abs(det) > detail::degenerate_ratio<T>())) {
        return detail::error<T>(function, "right, bottom and top planes do not span space (two are parallel)",
                                {{"determinant", det}});
    }
    // Cramer's rule, column by column.
    const Vec3<T> rhs(L);
    T k[3];
    for (int c = 0; c < 3; ++c) {
        Mat3<T> replaced = system;
        replaced[c] = rhs;
        k[c] = glm::determinant(replaced) / det;
    }
    const T k_r = k[0], k_b = k[1], k_t = k[2];

    // eq. 9: the four side planes meet in one point iff the w parts agree too.
    const T residual = -k_r * R.w + k_b * B.w + k_t * Tp.w - L.w;
    const T size = T(1) + std::abs(k_r * R.w) + std::abs(k_b * B.w) + std::abs(k_t * Tp.w) + std::abs(L.w);
    if (!(std::abs(residual) <= detail::concurrency_tolerance<T>() * size)) {
        return detail::error<T>(function, "side planes do not meet in one point (eq. 9)",
                                {{"residual", residual}});
    }
    if (!(k_r > T(0) && k_b > T(0) && k_t > T(0))) {
        return detail::error<T>(function,
                                "side planes must all face inward (K_r, K_b, K_t > 0 with K_l = 1)",
                                {{"K_r", k_r}, {"K_b", k_b}, {"K_t", k_t}});
    }
    SideRows<T> rows;
    rows.m0 = (L - k_r * R) / T(2);
    rows.m1 = (k_b * B - k_t * Tp) / T(2);
    rows.m3 = (L + k_r * R + k_b * B + k_t * Tp) / T(4); // both eq. 2 forms, averaged
    rows.near = unit[4];

    // The eye (where m0, m1, m3 vanish) must be on the near plane's negative side.
    const Vec4<T> eye = to_point(detail::cross4(rows.m0, rows.m1, rows.m3), infinity_tolerance<T>());
    if (eye.w == T(1)) {
        const T eye_distance = rows.near.distance(Vec3<T>(eye));
        if (!(eye_distance < T(0))) {
            return detail::error_text(function, "the eye must be on the near plane's negative side",
                                      "eye=" + detail::vector_text(Vec3<T>(eye)) +
                                          " distance=" + detail::number(eye_distance));
        }
    } else if (!(std::abs(glm::dot(rows.near.normal(), Vec3<T>(eye))) > detail::degenerate_ratio<T>())) {
        return detail::error_text(function, "near plane is parallel to the projection direction",
                                  "direction=" + detail::vector_text(Vec3<T>(eye)));
    }
    return rows;
}

template <class T>
Mat4<T> matrix_of(const SideRows<T>& rows, T k_near, DepthRange depth) {
    const T s = clip_z_span<T>(depth) > T(0) ? T(1) : T(-1);
    Mat4<T> m;
    set_row(m, 0, rows.m0);
    set_row(m, 1, rows.m1);
    set_row(m, 2, clip_z_near<T>(depth) * rows.m3 + s * k_near * rows.near.abcd);
    set_row(m, 3, rows.m3);
    return m;
}

template <class T>
Result<MatrixPair<T>> assemble(const SideRows<T>& rows, T k_near, DepthRange depth, const char* function) {
    const Mat4<T> m = matrix_of(rows, k_near, depth);
    const std::optional<Mat4<T>> inv = detail::inverse_from_rows(m);
    if (!inv) {
        return detail::error<T>(function, "planes give a degenerate frustum (far plane through the eye)",
                                {{"K_n", k_near}});
    }
    return detail::PairFactory::keep_sign(m, *inv, depth, false);
}

// The corrected §4.2 stop test: every far corner finite and in front.
template <class T>
bool far_corners_in_front(const MatrixPair<T>& pair) {
    const KeyPoints<T> points = key_points(pair);
    for (int i = 4; i < 8; ++i) {
        const Vec4<T>& c = points.corners[i];
        if (!(c.w > detail::degenerate_ratio<T>() * glm::length(Vec3<T>(c)))) {
            return false;
        }
    }
    return true;
}

} // namespace

namespace {

// eq. 12: F . Q = 0 with F = |z_f - z_n| m3 - K_n N, for one far point.
template <class T>
Result<T> k_near_through(const SideRows<T>& rows, const Vec3<T>& far_point, DepthRange depth) {
    const Vec4<T> q(far_point, T(1));
    if (!detail::finite3(far_point)) {
        return detail::error_text("from_planes", "far point must be finite", detail::vector_text(far_point));
    }
    const T in_front = glm::dot(rows.m3, q); // clip w of Q
    const T beyond_near = rows.near.evaluate(q);
    if (!(in_front > T(0)) || !(beyond_near > T(0))) {
        return detail::error_text("from_planes", "far point must be in front of the eye and beyond the near plane",
                                  "point=" + detail::vector_text(far_point) + " w=" + detail::number(in_front) +
                                      " near_distance=" + detail::number(beyond_near));
    }
    // K_n grows as w / near_distance (eq. 12): a far point on the near plane
    // up to rounding would give entries of 1e13 and a meaningless depth. Both
    // are lengths of the frustum's own scale (w: the depth from the eye, or
    // the half-size of an orthographic box), so their ratio is refused past
    // 1/sqrt(epsilon): 2896 in float, 6.7e7 in double.
    const T max_ratio = T(1) / std::sqrt(std::numeric_limits<T>::epsilon());
    if (!(in_front <= max_ratio * beyond_near)) {
        return detail::error_text("from_planes",
                                  "far point must lie clearly beyond the near plane (at least 1/" +
                                      detail::number(max_ratio) + " of its depth w)",
                                  "point=" + detail::vector_text(far_point) + " w=" + detail::number(in_front) +
                                      " near_distance=" + detail::number(beyond_near));
    }
    return std::abs(clip_z_span<T>(depth)) * in_front / beyond_near;
}

} // namespace

namespace {

// §4.1 for several points: the smallest K_n of them (F(Q_i) >= 0 for every
// point <=> K_n <= K_n(Q_i)).
template <class T>
Result<T> k_near_through_all(const SideRows<T>& rows, const Vec3<T>* far_points, std::size_t count,
                             DepthRange depth) {
    if (count == 0) {
        return detail::error_text("from_planes", "needs at least one far point", "none");
    }
    T k_near = std::numeric_limits<T>::infinity();
    for (std::size_t i = 0; i < count; ++i) {
        const auto k = k_near_through(rows, far_points[i], depth);
        if (!k) {
            return k.take_error();
        }
        k_near = std::min(k_near, *k);
    }
    return k_near;
}

} // namespace

template <class T>
Result<MatrixPair<T>> from_planes(const SidePlanes<T>& planes, const Vec3<T>& far_point, DepthRange depth) {
    return detail::from_planes_points(planes, &far_point, 1, depth);
}

template <class T>
Result<MatrixPair<T>> from_planes(const SidePlanes<T>& planes, const std::vector<Vec3<T>>& far_points,
                                  DepthRange depth) {
    return detail::from_planes_points(planes, far_points.data(), far_points.size(), depth);
}

namespace {

// §4.1's side rows and K_n for the far points (the checks of both, in order).
template <class T>
struct RowsAndK {
    SideRows<T> rows;
    T k_near;
};
template <class T>
Result<RowsAndK<T>> rows_through(const SidePlanes<T>& planes, const Vec3<T>* far_points, std::size_t count,
                                 DepthRange depth) {
    auto rows = side_rows(planes, "from_planes");
    if (!rows) {
        return rows.take_error();
    }
    const auto k_near = k_near_through_all(*rows, far_points, count, depth);
    if (!k_near) {
        return k_near.take_error();
    }
    return RowsAndK<T>{*rows, *k_near};
}

} // namespace

namespace detail {

// rows_through()'s rows and K_n made into the pair with its inverse
// (assemble()), or with kMatrixOnly into the matrix alone (matrix_of()).
template <class T, bool kMatrixOnly>
Result<std::conditional_t<kMatrixOnly, Mat4<T>, MatrixPair<T>>> through_far_points(
    const SidePlanes<T>& planes, const Vec3<T>* far_points, std::size_t count, DepthRange depth) {
    const auto found = rows_through(planes, far_points, count, depth);
    if (!found) {
        return found.take_error();
    }
    if constexpr (kMatrixOnly) {
        return matrix_of(found->rows, found->k_near, depth);
    } else {
        return assemble(found->rows, found->k_near, depth, "from_planes");
    }
}

template <class T>
Result<MatrixPair<T>> from_planes_points(const SidePlanes<T>& planes, const Vec3<T>* far_points, std::size_t count,
                                         DepthRange depth) {
    return through_far_points<T, false>(planes, far_points, count, depth);
}

template <class T>
Result<Mat4<T>> from_planes_matrix(const SidePlanes<T>& planes, const Vec3<T>* far_points, std::size_t count,
                                   DepthRange depth) {
    return through_far_points<T, true>(planes, far_points, count, depth);
}

} // namespace detail

template <class T>
Result<GrownFrustum<T>> from_planes_volume_growth(const SidePlanes<T>& planes, DepthRange depth,
                                                  int max_iterations) {
    const auto rows = side_rows(planes, "from_planes_volume_growth");
    if (!rows) {
        return rows.take_error();
    }
    const Vec4<T> n = rows->near.abcd;
    // eq. 13 (|N.xyz| = 1 after normalization): F perpendicular to N.
    T k_near = std::abs(clip_z_span<T>(depth)) * glm::dot(Vec3<T>(rows->m3), Vec3<T>(n));
    // The paper's delta, kept positive when eq. 13 gives K_n <= 0.
    const T base_step = (glm::length(n) + glm::length(rows->m3)) * T(0.1);
    T delta = k_near > T(0) ? std::min(base_step, k_near * T(0.1)) : base_step;
    for (int iteration = 0; iteration <= max_iterations; ++iteration) {
        auto pair = assemble(*rows, k_near, depth, "from_planes_volume_growth");
        if (pair && far_corners_in_front(*pair)) {
            return GrownFrustum<T>{std::move(pair).value(), iteration, k_near};
        }
        k_near += delta;
        delta *= T(2);
    }
    return detail::error<T>("from_planes_volume_growth", "no valid far plane within the iteration limit",
                            {{"max_iterations", T(max_iterations)}, {"K_n", k_near}});
}

#define FRUSTUM_INSTANTIATE(T)                                                                              \
    template Result<MatrixPair<T>> from_planes(const SidePlanes<T>&, const Vec3<T>&, DepthRange);           \
    template Result<MatrixPair<T>> from_planes(const SidePlanes<T>&, const std::vector<Vec3<T>>&, DepthRange); \
    template Result<GrownFrustum<T>> from_planes_volume_growth(const SidePlanes<T>&, DepthRange, int);     \
    template Result<MatrixPair<T>> detail::from_planes_points(const SidePlanes<T>&, const Vec3<T>*, std::size_t, \
                                                              DepthRange);                                     \
    template Result<Mat4<T>> detail::from_planes_matrix(const SidePlanes<T>&, const Vec3<T>*, std::size_t,       \
                                                        DepthRange);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
