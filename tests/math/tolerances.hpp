// Tolerances of the math suite with their reasoning: max_abs/max_diff,
// close()/close_abs(), inverse residuals, incidence, factor_between and
// the per-scalar tight()/loose() bounds.
#pragma once

#include "printers.hpp"
#include "support_basics.hpp"

namespace mtest {

// Largest |entry|.
template <int N, class T>
double max_abs(const glm::vec<N, T, glm::defaultp>& v) {
    double m = 0;
    for (int i = 0; i < N; ++i) m = std::max(m, std::abs(double(v[i])));
    return m;
}
template <class T>
double max_abs(const Mat4<T>& m) {
    double r = 0;
    for (int c = 0; c < 4; ++c) r = std::max(r, max_abs(m[c]));
    return r;
}
template <class T>
double max_abs(const Plane<T>& p) {
    return max_abs(p.abcd);
}

template <int N, class T>
double max_diff(const glm::vec<N, T, glm::defaultp>& a, const glm::vec<N, T, glm::defaultp>& b) {
    double m = 0;
    for (int i = 0; i < N; ++i) {
        const double d = std::abs(double(a[i]) - double(b[i]));
        m = (d > m || std::isnan(d)) ? d : m;
    }
    return m;
}
template <class T>
double max_diff(const Mat4<T>& a, const Mat4<T>& b) {
    double m = 0;
    for (int c = 0; c < 4; ++c) {
        const double d = max_diff(a[c], b[c]);
        m = (d > m || std::isnan(d)) ? d : m;
    }
    return m;
}
template <class T>
double max_diff(const Plane<T>& a, const Plane<T>& b) {
    return max_diff(a.abcd, b.abcd);
}

// `actual == close(expected, rel)`: every entry within rel * (largest
// |entry| of expected) of the expected one; NaN never compares equal.
// Use close_abs for an absolute tolerance.
template <class V>
Close<V> close(const V& expected, double relative) {
    return {expected, relative * std::max(max_abs(expected), 1e-300)};
}
template <class V>
Close<V> close_abs(const V& expected, double absolute) {
    return {expected, absolute};
}
template <class V>
bool operator==(const V& actual, const Close<V>& c) {
    const double d = max_diff(actual, c.expected);
    return d <= c.tolerance; // false for NaN
}

// Column-by-column relative difference: max_j max_i |a_ij - ref_ij| / max_i |ref_ij|.
// The columns of an inverse are key points of very different sizes (a
// direction of length 1e-3 next to a point 400 away), so each is compared
// on its own scale.
template <class T, class U>
double column_relative_diff(const Mat4<T>& a, const Mat4<U>& ref) {
    double worst = 0;
    for (int j = 0; j < 4; ++j) {
        const glm::dvec4 r(ref[j]);
        const double d = max_diff(glm::dvec4(a[j]), r) / std::max(max_abs(r), 1e-300);
        worst = (d > worst || std::isnan(d)) ? d : worst;
    }
    return worst;
}

// Componentwise relative residual of M * inv = I:
//   max_ij |(M inv - I)_ij| / (|M| |inv|)_ij
// (|.| entrywise). A product of two matrices whose entries carry relative
// errors of a few ulp has exactly this kind of error, whatever the scale of
// rows and columns (a projection's entries span 1e-3..1e3), so the bound
// is a small multiple of eps independent of the camera. Computed in double.
template <class T>
double inverse_residual(const Mat4<T>& m, const Mat4<T>& inv) {
    const glm::dmat4 a(m), b(inv);
    const glm::dmat4 product = a * b;
    double worst = 0;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            double bound = 0;
            for (int k = 0; k < 4; ++k) bound += std::abs(a[k][r]) * std::abs(b[c][k]);
            const double error = std::abs(product[c][r] - (c == r ? 1.0 : 0.0));
            if (std::isnan(error)) return std::numeric_limits<double>::infinity();
            if (error == 0) continue;
            worst = bound > 0 ? std::max(worst, error / bound) : std::numeric_limits<double>::infinity();
        }
    }
    return worst;
}
template <class T>
double inverse_residual(const MatrixPair<T>& p) {
    return inverse_residual(p.matrix(), p.inverse());
}

// Normwise residual: max |(M inv - I)_ij| / (max|M| max|inv|). Weaker than
// the componentwise one, for long chains of analytic updates.
template <class T>
double inverse_residual_normwise(const MatrixPair<T>& p) {
    const glm::dmat4 a(p.matrix()), b(p.inverse());
    const double d = max_diff(glm::dmat4(a * b), glm::dmat4(1.0));
    return d / (max_abs(a) * max_abs(b));
}

// The 4D cosine between a plane and a homogeneous point: a scale-free
// incidence measure, 0 when the point lies on the plane. Rounding in the
// plane (rows of M) and in the point (columns of M^-1) perturbs it by
// O(eps * cond), independently of how far the point is from the origin.
template <class T>
double incidence(const Plane<T>& plane, const Vec4<T>& h) {
    const glm::dvec4 a(plane.abcd), b(h);
    return glm::dot(a, b) / (glm::length(a) * glm::length(b));
}

// Scalar factor lambda minimizing |b - lambda a| (least squares) and the
// max residual |b - lambda a| relative to max|b|. Used for "equal up to a
// (positive) factor".
struct Factor {
    double lambda;
    double residual;
};
template <class T>
Factor factor_between(const Mat4<T>& a, const Mat4<T>& b) {
    double ab = 0, aa = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            ab += double(a[c][r]) * double(b[c][r]);
            aa += double(a[c][r]) * double(a[c][r]);
        }
    const double lambda = ab / aa;
    const glm::dmat4 scaled = glm::dmat4(a) * lambda;
    return {lambda, max_diff(scaled, glm::dmat4(b)) / max_abs(b)};
}
template <class T>
Factor factor_between(const Vec4<T>& a, const Vec4<T>& b) {
    const glm::dvec4 da(a), db(b);
    const double lambda = glm::dot(da, db) / glm::dot(da, da);
    return {lambda, max_diff(glm::dvec4(da * lambda), db) / max_abs(db)};
}

// Per-scalar tolerances used throughout, with the reason:
//  - tight():  results of a few dozen flops on well-scaled data (one
//    constructor, one crop): 64 ulp of the scalar.
//  - loose():  results passing through a camera with far/near up to 200
//    and coordinates up to ~400 (a rotated view composed with a projection,
//    corners read from the inverse): float loses ~log2(cond) ~ 10 bits, so
//    2e-4 for float; double has 29 more bits, so 1e-12.
template <class T>
constexpr double tight() {
    return 64 * double(eps<T>());
}
template <class T>
constexpr double loose() {
    return sizeof(T) == sizeof(float) ? 2e-4 : 1e-12;
}

} // namespace mtest
