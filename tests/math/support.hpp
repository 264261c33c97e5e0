// Shared helpers of the math suite: printers (so a failing CHECK shows
// numbers), tolerance helpers with their reasoning, and
// a deterministic generator of random, well-conditioned cameras.
//
// Conventions used by every test (see frustum/include/frustum/*.hpp):
// column vectors, clip = M * world; a MatrixPair is scaled so that w > 0
// inside; planes are inward-positive.
#pragma once

#include <doctest/doctest.h>
#include <frustum/frustum.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

// Set when built with -DFRUSTUM_SANITIZE=ON (ASan + UBSan, which traps a
// float division by zero): the few inputs that make the library divide by
// zero are then left out, so one known problem cannot abort the suite.
#if defined(__SANITIZE_ADDRESS__)
#define MTEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MTEST_SANITIZED 1
#endif
#endif
#ifndef MTEST_SANITIZED
#define MTEST_SANITIZED 0
#endif

namespace mtest {

using frustum::DepthRange;
using frustum::Mat4;
using frustum::MatrixPair;
using frustum::Plane;
using frustum::Vec3;
using frustum::Vec4;

constexpr DepthRange all_depth_ranges[3] = {DepthRange::ZeroToOne, DepthRange::MinusOneToOne,
                                            DepthRange::ReversedZeroToOne};

constexpr double pi = 3.14159265358979323846;

template <class T>
constexpr T eps() {
    return std::numeric_limits<T>::epsilon();
}

// ---------------------------------------------------------------- printing

template <class T>
std::string num(T v) {
    std::ostringstream s;
    s << std::setprecision(std::numeric_limits<T>::max_digits10) << v;
    return s.str();
}

template <int N, class T>
std::string vec_text(const glm::vec<N, T, glm::defaultp>& v) {
    std::string s = "(";
    for (int i = 0; i < N; ++i) {
        s += (i ? ", " : "") + num(v[i]);
    }
    return s + ")";
}

// Printed by ROWS, as the maths is written (GLM stores columns).
template <class T>
std::string mat_text(const Mat4<T>& m) {
    std::string s = "rows[";
    for (int r = 0; r < 4; ++r) {
        s += (r ? ", " : "") + vec_text(frustum::row(m, r));
    }
    return s + "]";
}

template <class T>
std::string pair_text(const MatrixPair<T>& p) {
    return std::string("MatrixPair{depth=") + std::string(frustum::to_string(p.depth())) +
           " flips_winding=" + (p.flips_winding() ? "true" : "false") + " matrix=" + mat_text(p.matrix()) +
           " inverse=" + mat_text(p.inverse()) + "}";
}

// A value compared within an absolute tolerance (see close()).
template <class V>
struct Close {
    V expected;
    double tolerance;
};

} // namespace mtest

namespace doctest {

template <class T>
struct StringMaker<glm::vec<3, T, glm::defaultp>> {
    static String convert(const glm::vec<3, T, glm::defaultp>& v) { return mtest::vec_text(v).c_str(); }
};
template <class T>
struct StringMaker<glm::vec<4, T, glm::defaultp>> {
    static String convert(const glm::vec<4, T, glm::defaultp>& v) { return mtest::vec_text(v).c_str(); }
};
template <class T>
struct StringMaker<glm::mat<4, 4, T, glm::defaultp>> {
    static String convert(const glm::mat<4, 4, T, glm::defaultp>& m) { return mtest::mat_text(m).c_str(); }
};
template <class T>
struct StringMaker<frustum::Plane<T>> {
    static String convert(const frustum::Plane<T>& p) { return ("Plane" + mtest::vec_text(p.abcd)).c_str(); }
};
template <class T>
struct StringMaker<frustum::MatrixPair<T>> {
    static String convert(const frustum::MatrixPair<T>& p) { return mtest::pair_text(p).c_str(); }
};
template <class V>
struct StringMaker<mtest::Close<V>> {
    static String convert(const mtest::Close<V>& c) {
        return (StringMaker<V>::convert(c.expected) + " +- " + mtest::num(c.tolerance).c_str());
    }
};

} // namespace doctest

namespace mtest {

// ------------------------------------------------------------- tolerances

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

// ------------------------------------------------------- random cameras

// A small deterministic generator (splitmix64): identical sequences on
// every platform and standard library, unlike std::uniform_*_distribution.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t bits() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return double(bits() >> 11) * 0x1.0p-53; } // [0, 1)
    double uniform(double a, double b) { return a + (b - a) * uniform(); }
    int index(int n) { return int(bits() % std::uint64_t(n)); }
    bool coin() { return (bits() >> 63) != 0; }
    DepthRange depth() { return all_depth_ranges[index(3)]; }
    glm::dvec3 in_box(double half) { return {uniform(-half, half), uniform(-half, half), uniform(-half, half)}; }
    glm::dvec3 unit_vector() {
        for (;;) {
            const glm::dvec3 v = in_box(1.0);
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1.0) return v / l;
        }
    }

private:
    std::uint64_t state_;
};

enum class Kind { Perspective, OffAxis, Orthographic };

inline const char* kind_name(Kind k) {
    return k == Kind::Perspective ? "perspective" : k == Kind::OffAxis ? "off_axis" : "orthographic";
}

// Everything needed to rebuild a camera, in double; `make<T>` builds it in
// T through the library's own constructors (so float tests exercise the
// float code paths, not a cast).
struct CameraSpec {
    Kind kind = Kind::Perspective;
    DepthRange depth = DepthRange::ZeroToOne;
    bool infinite = false; // perspective kinds only
    bool rotated = true;   // compose with a look_at view
    double fovy = 1, aspect = 1;
    double left = -1, right = 1, bottom = -1, top = 1;
    double near_m = 1, far_m = 10;
    glm::dvec3 eye{0}, target{0, 0, -1}, up{0, 1, 0};

    std::string text() const {
        std::ostringstream s;
        s << std::setprecision(17) << kind_name(kind) << " depth=" << frustum::to_string(depth)
          << (infinite ? " far=inf" : "") << " fovy=" << fovy << " aspect=" << aspect << " lrbt=(" << left << ", "
          << right << ", " << bottom << ", " << top << ") near=" << near_m << " far=" << far_m;
        if (rotated) s << " eye=" << vec_text(eye) << " target=" << vec_text(target) << " up=" << vec_text(up);
        return s.str();
    }
};

struct CameraOptions {
    bool perspective = true;
    bool off_axis = true;
    bool orthographic = true;
    bool infinite = true; // allow infinite far for the perspective kinds
    bool rotated = true;
};

// Well-conditioned by construction: fovy 30..110 degrees, aspect 0.5..2,
// near 0.1..2, far/near 5..200; off-axis windows shifted by up to 80% of
// their half size; orthographic boxes 1..20 wide, shifted by up to 5;
// eyes in [-20, 20]^3 looking 1..10 away, up at least ~12 degrees off the
// viewing direction.
inline CameraSpec random_camera(Random& rng, const CameraOptions& options = {}) {
    CameraSpec c;
    std::vector<Kind> kinds;
    if (options.perspective) kinds.push_back(Kind::Perspective);
    if (options.off_axis) kinds.push_back(Kind::OffAxis);
    if (options.orthographic) kinds.push_back(Kind::Orthographic);
    c.kind = kinds[std::size_t(rng.index(int(kinds.size())))];
    c.depth = rng.depth();
    c.fovy = rng.uniform(30, 110) * pi / 180;
    c.aspect = rng.uniform(0.5, 2);
    if (c.kind == Kind::Orthographic) {
        const double hw = rng.uniform(0.5, 10), hh = rng.uniform(0.5, 10);
        const double cx = rng.uniform(-5, 5), cy = rng.uniform(-5, 5);
        c.left = cx - hw, c.right = cx + hw, c.bottom = cy - hh, c.top = cy + hh;
        c.near_m = rng.uniform(-5, 5);
        c.far_m = c.near_m + rng.uniform(1, 100);
    } else {
        c.near_m = rng.uniform(0.1, 2);
        c.far_m = c.near_m * rng.uniform(5, 200);
        c.infinite = options.infinite && rng.index(3) == 0;
        if (c.kind == Kind::OffAxis) {
            const double hw = c.near_m * rng.uniform(0.3, 1.5), hh = c.near_m * rng.uniform(0.3, 1.5);
            const double cx = hw * rng.uniform(-0.8, 0.8), cy = hh * rng.uniform(-0.8, 0.8);
            c.left = cx - hw, c.right = cx + hw, c.bottom = cy - hh, c.top = cy + hh;
        }
    }
    c.rotated = options.rotated;
    if (c.rotated) {
        c.eye = rng.in_box(20);
        const glm::dvec3 dir = rng.unit_vector();
        c.target = c.eye + dir * rng.uniform(1, 10);
        do {
            c.up = rng.unit_vector();
        } while (glm::length(glm::cross(dir, c.up)) < 0.2);
    }
    return c;
}

template <class T>
frustum::Result<MatrixPair<T>> try_make(const CameraSpec& c) {
    using frustum::Result;
    std::optional<T> far;
    if (!c.infinite) far = T(c.far_m);
    Result<MatrixPair<T>> projection =
        c.kind == Kind::Perspective ? frustum::perspective<T>(T(c.fovy), T(c.aspect), T(c.near_m), far, c.depth)
        : c.kind == Kind::OffAxis
            ? frustum::off_axis<T>(T(c.left), T(c.right), T(c.bottom), T(c.top), T(c.near_m), far, c.depth)
            : frustum::orthographic<T>(T(c.left), T(c.right), T(c.bottom), T(c.top), T(c.near_m), T(c.far_m),
                                       c.depth);
    if (!projection || !c.rotated) return projection;
    const auto view = frustum::look_at<T>(Vec3<T>(c.eye), Vec3<T>(c.target), Vec3<T>(c.up));
    if (!view) return frustum::Error{view.error()};
    return frustum::compose(*projection, *view);
}

// Builds the camera; a failure is a test failure (the generator only makes
// valid cameras), reported with the camera.
template <class T>
MatrixPair<T> make(const CameraSpec& c) {
    auto pair = try_make<T>(c);
    INFO("camera: ", c.text());
    REQUIRE_MESSAGE(pair.ok(), pair.error());
    return *pair;
}

// ----------------------------------------------------------- clip space

// World (homogeneous) point of a clip-space point.
template <class T>
Vec4<T> unproject(const MatrixPair<T>& p, const Vec4<T>& clip) {
    return p.inverse() * clip;
}

// Clip z of a fraction t in [0, 1] of the way from the near to the far
// plane (in clip z, not in eye depth).
template <class T>
T clip_z_at(DepthRange d, double t) {
    return T(frustum::clip_z_near<double>(d) + t * frustum::clip_z_span<double>(d));
}

// Inside test in clip space with a margin (|x| <= w etc.; z between the
// depth range's ends, whatever their order).
template <class T>
bool clip_inside(const Vec4<T>& c, DepthRange d, double margin = 0) {
    const double w = c.w;
    if (!(w > 0)) return false;
    const double zn = frustum::clip_z_near<double>(d), zf = frustum::clip_z_far<double>(d);
    const double lo = std::min(zn, zf), hi = std::max(zn, zf);
    const double m = margin * w;
    return std::abs(double(c.x)) <= w - m && std::abs(double(c.y)) <= w - m && double(c.z) >= lo * w + m &&
           double(c.z) <= hi * w - m;
}

// A plane's value at a world point given homogeneously with w > 0.
template <class T>
double side(const Plane<T>& plane, const Vec4<T>& h) {
    return double(plane.evaluate(h)) / double(h.w);
}

// A random clip-space point strictly inside the clip box: x, y within
// [-1 + margin, 1 - margin], z a fraction margin..1-margin of the way from
// z_near to z_far, w = 1.
inline glm::dvec4 random_clip_point(Random& rng, DepthRange d, double margin) {
    return {rng.uniform(-1 + margin, 1 - margin), rng.uniform(-1 + margin, 1 - margin),
            clip_z_at<double>(d, rng.uniform(margin, 1 - margin)), 1};
}

// The plane c (world) seen in the pair's clip space: c'_j = c . (column j
// of M^-1), so that c' . (M p) = c . p.
template <class T>
glm::dvec4 clip_space_plane(const MatrixPair<T>& pair, const Plane<T>& c) {
    const glm::dmat4 inv(pair.inverse());
    const glm::dvec4 cw(c.abcd);
    return {glm::dot(cw, inv[0]), glm::dot(cw, inv[1]), glm::dot(cw, inv[2]), glm::dot(cw, inv[3])};
}

// A random world plane through a random point inside the pair's frustum,
// made in clip space (c' = (n', -n'.p0), world c = M^T c', normalized).
// eye_behind: the eye on the plane's negative side (clip_oblique's rule:
// (z_f - z_n) c'_z > 0); otherwise on its positive side (mirror's rule).
// The clip-space tilt is at most 45 degrees off the z axis in x and y.
template <class T>
Plane<T> random_plane_through(Random& rng, const MatrixPair<T>& pair, bool eye_behind) {
    const DepthRange d = pair.depth();
    const double s = frustum::clip_z_span<double>(d) > 0 ? 1 : -1;
    const glm::dvec4 p0 = random_clip_point(rng, d, 0.1);
    // One draw per statement (argument order is unspecified), z first.
    const double n_z = (eye_behind ? s : -s) * rng.uniform(0.2, 1);
    const double n_y = rng.uniform(-1, 1);
    const double n_x = rng.uniform(-1, 1);
    const glm::dvec3 n(n_x, n_y, n_z);
    const glm::dvec4 clip_plane(n, -glm::dot(n, glm::dvec3(p0)));
    const glm::dvec4 c = glm::transpose(glm::dmat4(pair.matrix())) * clip_plane;
    return Plane<T>(Vec4<T>(c / glm::length(glm::dvec3(c))));
}

// Where the plane cuts the four side edges of the frustum: the smallest
// w / |h| of the four cut points h (homogeneous, world). Positive: all four
// in front of the eye (the near face is then a bounded convex quad);
// negative: some edge meets the plane only behind the eye. The edge
// x = +-w, y = +-w meets c' at clip z* = -(c'_x x + c'_y y + c'_w)/c'_z.
template <class T>
double edge_cut_margin(const MatrixPair<T>& pair, const Plane<T>& c) {
    const glm::dvec4 cc = clip_space_plane(pair, c);
    const glm::dmat4 inv(pair.inverse());
    if (cc.z == 0) return 0;
    double worst = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 4; ++j) {
        const glm::dvec4 q = frustum::clip_corner<double>(j, pair.depth());
        const double z = -(cc.x * q.x + cc.y * q.y + cc.w) / cc.z;
        const glm::dvec4 h = inv * glm::dvec4(q.x, q.y, z, 1);
        worst = std::min(worst, h.w / glm::length(h));
    }
    return worst;
}
template <class T>
bool cuts_all_edges_in_front(const MatrixPair<T>& pair, const Plane<T>& c) {
    return edge_cut_margin(pair, c) > 0;
}

// Rows of a GLM matrix set in reading order (what a literal looks like in
// a paper): mat_rows({a,b,c,d}, {...}, ...).
template <class T>
Mat4<T> mat_rows(const Vec4<T>& r0, const Vec4<T>& r1, const Vec4<T>& r2, const Vec4<T>& r3) {
    Mat4<T> m;
    frustum::set_row(m, 0, r0);
    frustum::set_row(m, 1, r1);
    frustum::set_row(m, 2, r2);
    frustum::set_row(m, 3, r3);
    return m;
}

} // namespace mtest
