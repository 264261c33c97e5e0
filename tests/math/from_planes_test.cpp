// Matrix from planes (paper §4, from_planes.hpp): the far-point variant
// (§4.1) rebuilds a camera's matrix up to a POSITIVE factor; the volume
// growth loop (§4.2 with erratum 12) gives valid frustums in few steps.
#include "support.hpp"

using namespace mtest;
using frustum::DepthRange;
using frustum::SidePlanes;

namespace {

template <class T>
SidePlanes<T> side_planes_of(const MatrixPair<T>& pair) {
    const auto p = frustum::raw_planes(pair);
    return {p.left, p.right, p.bottom, p.top, p.near};
}

// Rotates a plane about an axis through a point on it.
template <class T>
Plane<T> tilted(const Plane<T>& plane, const glm::dvec3& on_plane, const glm::dvec3& axis, double angle) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(plane.normal()));
    const glm::dvec3 a = glm::normalize(axis);
    const glm::dvec3 r = n * std::cos(angle) + glm::cross(a, n) * std::sin(angle) + a * glm::dot(a, n) * (1 - std::cos(angle));
    return Plane<T>(Vec4<T>(glm::dvec4(r, -glm::dot(r, on_plane))));
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("from_planes: the landmark's planes and far corner give the landmark back", T, float, double) {
    // The 90-degree camera's planes (see planes_test) and its far corner
    // C5 = (10, 10, -10). The rows come back scaled by 1/|L_raw| = 1/sqrt2
    // (planes are normalized inside), so compare up to a positive factor.
    for_each_depth_range([&](DepthRange depth) {
        const auto pair = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), depth);
        REQUIRE(pair.ok());
        const auto rebuilt = frustum::from_planes(side_planes_of(*pair), Vec3<T>(10, 10, -10), depth);
        REQUIRE_MESSAGE(rebuilt.ok(), rebuilt.error());
        CHECK(rebuilt->depth() == depth);
        const Factor f = factor_between(pair->matrix(), rebuilt->matrix());
        CHECK(f.lambda == doctest::Approx(1 / std::sqrt(2.0)).epsilon(loose<T>()));
        CHECK(f.residual <= loose<T>());
        CHECK(inverse_residual(*rebuilt) <= 64 * eps<T>());
        // Another far point on the same far plane gives the same matrix.
        const auto again = frustum::from_planes(side_planes_of(*pair), Vec3<T>(-3, 7, -10), depth);
        REQUIRE(again.ok());
        CHECK(again->matrix() == close(rebuilt->matrix(), loose<T>()));
    });
}

TEST_CASE_TEMPLATE("from_planes rebuilds random perspective matrices up to a positive factor, every depth range", T,
                   float, double) {
    Random rng(41);
    CameraOptions options;
    options.orthographic = false; // see the next test
    options.infinite = false;     // the far point must be a finite far corner
    for (int i = 0; i < 1500; ++i) {
        const CameraSpec c = random_camera(rng, options);
        const MatrixPair<T> pair = make<T>(c);
        INFO(c.text());
        const Vec4<T> corner = frustum::key_points(pair).corners[std::size_t(4 + rng.index(4))];
        REQUIRE(corner.w > 0);
        const auto rebuilt = frustum::from_planes(side_planes_of(pair), Vec3<T>(corner) / corner.w, c.depth);
        REQUIRE_MESSAGE(rebuilt.ok(), rebuilt.error());
        const Factor f = factor_between(pair.matrix(), rebuilt->matrix());
        CHECK(f.lambda > 0); // a negative factor would flip every plane
        CHECK(f.residual <= loose<T>());
        CHECK(rebuilt->depth() == c.depth);
        CHECK(column_relative_diff(rebuilt->inverse(), glm::inverse(glm::dmat4(rebuilt->matrix()))) <= loose<T>());
    }
}

TEST_CASE_TEMPLATE("from_planes: an orthographic frustum's parallel side planes are rejected (known limitation)", T,
                   float, double) {
    // Eq. 10 solves for K_r, K_b, K_t with the 3x3 matrix of the normals of
    // R, B, T: B and T of a box are parallel, the matrix is singular, so §4
    // cannot rebuild an orthographic camera (its eye is at infinity).
    const auto box = frustum::orthographic<T>(-2, 2, -1, 1, 1, 11, DepthRange::ZeroToOne);
    REQUIRE(box.ok());
    const auto rebuilt = frustum::from_planes(side_planes_of(*box), Vec3<T>(2, 1, -11), DepthRange::ZeroToOne);
    REQUIRE_FALSE(rebuilt.ok());
    CHECK(rebuilt.error() ==
          "frustum::from_planes(): right, bottom and top planes do not span space (two are parallel), got determinant=0");
}

TEST_CASE_TEMPLATE("from_planes_volume_growth: untilted near plane needs at least one step (erratum 12)", T, float,
                   double) {
    // Eq. 13 is meant to make F perpendicular to N; for an untilted near
    // plane (m3.xyz parallel to N.xyz) it makes F's normal zero instead: an
    // infinite far plane, far corners at w = 0. The paper's stop test never
    // fires (near corners are on N, so F.C_i = -m3.C_i whatever K_n); the
    // corrected one (far corners finite, in front) must grow K_n.
    for_each_depth_range([&](DepthRange depth) {
        const auto pair = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), depth);
        REQUIRE(pair.ok());
        const auto grown = frustum::from_planes_volume_growth(side_planes_of(*pair), depth);
        REQUIRE_MESSAGE(grown.ok(), grown.error());
        CHECK(grown->iterations >= 1);
        CHECK(grown->iterations <= 8);
        CHECK(frustum::validate(grown->pair).valid());
        const auto p = frustum::planes(grown->pair);
        REQUIRE(p.far.has_value());
        // The far plane is parallel to the near one (z = const) behind it.
        CHECK(p.far->normal() == close_abs(Vec3<T>(0, 0, 1), loose<T>()));
        CHECK(p.far->offset() > T(1)); // z + d >= 0: the far plane z = -d is beyond z = -1
        // The paper's loop condition, (F.C1)(F.Ci) <= 0 for some i with
        // F = K_n N - m3, is false for ANY K_n: it would never iterate.
        const auto k = frustum::key_points(grown->pair);
        const Vec4<T> n = frustum::raw_planes(grown->pair).near.abcd;
        const Vec4<T> m3 = frustum::row(grown->pair.matrix(), 3);
        for (const T k_n : {T(0), grown->k_near, T(1000)}) {
            const Vec4<T> f = k_n * n - m3;
            for (int i = 1; i < 4; ++i) {
                CHECK(glm::dot(f, k.corners[0]) * glm::dot(f, k.corners[std::size_t(i)]) > 0);
            }
        }
        // Without any step allowed there is no valid far plane.
        const auto none = frustum::from_planes_volume_growth(side_planes_of(*pair), depth, 0);
        REQUIRE_FALSE(none.ok());
        CHECK(none.error().find("no valid far plane within the iteration limit") != std::string::npos);
    });
}

TEST_CASE_TEMPLATE("from_planes_volume_growth: random frustums with tilted near planes are valid, few steps", T, float,
                   double) {
    Random rng(42);
    CameraOptions options;
    options.orthographic = false;
    int worst_iterations = 0, tested = 0;
    for (int i = 0; i < 1000; ++i) {
        const CameraSpec c = random_camera(rng, options);
        const MatrixPair<T> pair = make<T>(c);
        INFO(c.text());
        SidePlanes<T> planes = side_planes_of(pair);
        // Tilt the near plane by up to 40 degrees about a random axis in it,
        // through the near face's centre: the eye stays behind it.
        const auto k = frustum::key_points(pair);
        const glm::dvec4 c0(k.corners[0]), c2(k.corners[2]);
        const glm::dvec3 centre = (glm::dvec3(c0) / c0.w + glm::dvec3(c2) / c2.w) / 2.0;
        const glm::dvec3 n(planes.near.normal());
        const glm::dvec3 axis = glm::cross(n, rng.unit_vector());
        const double angle = rng.uniform(-40, 40) * pi / 180;
        if (glm::length(axis) > 0.1) planes.near = tilted(planes.near, centre, axis, angle);
        CAPTURE(angle);
        // A frustum needs every side edge to cross the near plane in front
        // of the eye: skip tilts that make an edge ray (eye -> near corner,
        // up to ~66 degrees off the axis here) nearly parallel to the plane.
        const glm::dvec4 eye(k.eye);
        bool edges_cross = true;
        for (int j = 0; j < 4; ++j) {
            const glm::dvec4 cj(k.corners[std::size_t(j)]);
            const glm::dvec3 edge = glm::normalize(glm::dvec3(cj) / cj.w - glm::dvec3(eye) / eye.w);
            edges_cross = edges_cross && glm::dot(edge, glm::normalize(glm::dvec3(planes.near.normal()))) > 0.2;
        }
        if (!edges_cross) continue;
        ++tested;
        const auto grown = frustum::from_planes_volume_growth(planes, c.depth);
        REQUIRE_MESSAGE(grown.ok(), grown.error());
        const frustum::Validation v = frustum::validate(grown->pair);
        CHECK_MESSAGE(v.valid(), v.reason());
        CHECK(grown->iterations <= 8);
        worst_iterations = std::max(worst_iterations, grown->iterations);
        CHECK(grown->pair.depth() == c.depth);
        CHECK(inverse_residual(grown->pair) <= 256 * eps<T>());
        // The given planes are the result's planes (up to normalization).
        const auto p = frustum::planes(grown->pair);
        CHECK(p.near == close_abs(planes.near.normalized(), loose<T>() * (1 + max_abs(p.near))));
        CHECK(p.left == close_abs(planes.left.normalized(), loose<T>() * (1 + max_abs(p.left))));
        CHECK(p.top == close_abs(planes.top.normalized(), loose<T>() * (1 + max_abs(p.top))));
    }
    CHECK(worst_iterations <= 8);
    CHECK(tested > 600); // 769 of 1000 with this seed
}

} // TEST_SUITE
