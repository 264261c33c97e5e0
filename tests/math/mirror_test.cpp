// mirror() (paper §5.2): reflect in a plane, then clip obliquely by it.
// What the mirror pass shows is exactly the reflection of what lies behind
// the mirror inside the original view.
#include "support.hpp"

using namespace mtest;
using frustum::DepthRange;
using frustum::infinite_far;

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("mirror of the landmark in the plane z = -5: literal matrix", T, float, double) {
    // Camera: 90 degrees, near 1, far 10, at the origin looking down -z.
    // Mirror c = (0, 0, 1, 5) (z = -5, the eye on its positive side).
    // Reflection R: (x, y, z) -> (x, y, -10 - z); the reflected eye is at
    // (0, 0, -10) looking along +z, and clipping by the mirror (parallel to
    // the near plane) moves the near plane to the mirror, 5 away, while the
    // far plane stays 10 away. So the result is P5 * R with P5 the
    // perspective with near 5, far 10 (window [-5, 5]^2 at 5):
    //   P5 (ZeroToOne) rows (1,0,0,0), (0,1,0,0), (0,0,-2,-10), (0,0,-1,0)
    //   R rows (1,0,0,0), (0,1,0,0), (0,0,-1,-10), (0,0,0,1)
    //   P5 R rows (1,0,0,0), (0,1,0,0), (0,0,2,10), (0,0,1,10).
    // Check: z = -5 (mirror) -> w = 5, z = 0: depth 0; z = 0 -> w = 10,
    // z = 10: depth 1 (the reflection of the far plane z = -10).
    const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), DepthRange::ZeroToOne);
    REQUIRE(base.ok());
    const auto m = frustum::mirror(*base, Plane<T>(0, 0, 1, 5));
    REQUIRE_MESSAGE(m.ok(), m.error());
    CHECK(m->matrix() == close(from_rows<T>({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 2, 10}, {0, 0, 1, 10}), tight<T>()));
    CHECK(m->flips_winding());
    CHECK(inverse_residual(*m) <= 64 * eps<T>());
    // The same through other paths, in every depth range: reflect the
    // camera whose near plane is already at 5.
    for_each_depth_range([&](DepthRange depth) {
        const auto b = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), depth);
        const auto near5 = frustum::off_axis<T>(-5, 5, -5, 5, 5, T(10), depth);
        REQUIRE((b.ok() && near5.ok()));
        const auto mirrored = frustum::mirror(*b, Plane<T>(0, 0, 1, 5));
        const auto expected = frustum::reflect(*near5, Plane<T>(0, 0, 1, 5));
        REQUIRE((mirrored.ok() && expected.ok()));
        CHECK(mirrored->matrix() == close(expected->matrix(), tight<T>()));
        CHECK(mirrored->inverse() == close(expected->inverse(), tight<T>()));
        // (1, 2, -3) is the reflection of (1, 2, -7), which the camera sees
        // there: same clip x, y, w (only depth differs, the near plane moved).
        const Vec4<T> a = mirrored->matrix() * Vec4<T>(1, 2, -3, 1);
        const Vec4<T> o = b->matrix() * Vec4<T>(1, 2, -7, 1);
        CHECK(Vec4<T>(a.x, a.y, 0, a.w) == close(Vec4<T>(o.x, o.y, 0, o.w), tight<T>()));
        // Behind the mirror's surface (z < -5: reflections of points between
        // the eye and the mirror) nothing is shown; in front of it, yes.
        CHECK_FALSE(clip_inside(Vec4<T>(mirrored->matrix() * Vec4<T>(0, 0, -6, 1)), depth));
        CHECK(clip_inside(Vec4<T>(mirrored->matrix() * Vec4<T>(0, 0, -4, 1)), depth));
    });
}

TEST_CASE_TEMPLATE("mirror of a camera looking slightly up over water keeps w > 0 inside", T, float, double) {
    // A common case: eye (0, 2, 0) looking at (0, 2.5, -10) (2.9 degrees
    // up), 60 degrees, water plane y = 0. The point (0, 1, -10) above the
    // water has its reflection (0, -1, -10) in view, 19.6 degrees below the
    // view axis (< 30), and the ray to it meets the water at (0, 0, -6.67)
    // in front of the eye: so the mirror pass must draw (0, 1, -10), with
    // the same clip w as the original view gives its reflection (rows 0, 1,
    // 3 of the mirror pair are those of the reflected pair, M R). The
    // reflected camera looks 2.9 degrees DOWN from (0, -2, 0): its view
    // axis meets y = 0 only behind the eye.
    for_each_depth_range([&](DepthRange depth) {
        const auto projection = frustum::perspective<T>(T(pi / 3), 1, T(0.1), T(100), depth);
        const auto view = frustum::look_at<T>({0, 2, 0}, {0, T(2.5), -10}, {0, 1, 0});
        REQUIRE((projection.ok() && view.ok()));
        const MatrixPair<T> camera = frustum::compose(*projection, *view);
        const Vec4<T> seen = camera.matrix() * Vec4<T>(0, -1, -10, 1);
        REQUIRE(clip_inside(seen, depth));
        const auto m = frustum::mirror(camera, Plane<T>(0, 1, 0, 0));
        REQUIRE_MESSAGE(m.ok(), m.error());
        const Vec4<T> shown = m->matrix() * Vec4<T>(0, 1, -10, 1);
        CHECK(shown.w == doctest::Approx(seen.w).epsilon(1e-5));
        CHECK(clip_inside(shown, depth));
    });
}

TEST_CASE_TEMPLATE("mirror semantics on random cameras and mirrors", T, float, double) {
    // A random plane through the frustum with the eye in front of it. For
    // sampled points p of the original frustum:
    //   behind the mirror (c(p) < 0): the camera sees p in the mirror, so
    //     its reflection R p must be inside the mirror frustum;
    //   in front of it (c(p) > 0): R p lies behind the mirror and must be
    //     outside (nothing behind the mirror's surface leaks in).
    // Also: mirror == clip_oblique(reflect(.)), near plane == mirror plane,
    // winding flipped. The overall sign is counted separately (see
    // oblique_clip_test: a negated pair has w < 0 inside).
    const double delta = sizeof(T) == sizeof(float) ? 1e-2 : 1e-6;
    const double tol = sizeof(T) == sizeof(float) ? 1e-4 : 1e-10;
    int negated = 0, seen_in_mirror = 0, in_front = 0;
    for_each_random_camera<T>(71, 1000, [&](Random& rng, const CameraSpec& c, const MatrixPair<T>& pair) {
        const Plane<T> plane = random_plane_through(rng, pair, false);
        INFO("mirror ", vec_text(plane.abcd));
        const auto m = frustum::mirror(pair, plane);
        REQUIRE_MESSAGE(m.ok(), m.error());
        const auto r = frustum::reflect(pair, plane);
        REQUIRE(r.ok());
        const auto two_step = frustum::clip_oblique(*r, plane);
        REQUIRE(two_step.ok());
        // mirror() carries the plane into clip space exactly (R^T c = -c)
        // instead of through the reflected inverse, so it may differ from
        // the two-step path by rounding only.
        // (Tolerance of the analytic inverse, see oblique_clip_test.)
        const double analytic = sizeof(T) == sizeof(float) ? 2e-3 : 1e-10;
        CHECK(column_relative_diff(m->matrix(), two_step->matrix()) <= loose<T>());
        CHECK(column_relative_diff(m->inverse(), two_step->inverse()) <= analytic);
        CHECK(m->flips_winding());
        const double sign = glm::dot(glm::dvec4(frustum::row(m->matrix(), 3)),
                                     glm::dvec4(frustum::row(r->matrix(), 3))) > 0 ? 1 : -1;
        negated += sign < 0;
        const glm::dmat4 mm = glm::dmat4(m->matrix()) * sign;
        const glm::dmat4 reflection = frustum::reflection_matrix(Plane<double>(glm::dvec4(plane.abcd)));
        const glm::dvec4 cc = clip_space_plane(pair, plane);
        for (int s = 0; s < 30; ++s) {
            const glm::dvec4 u = random_clip_point(rng, c.depth, delta);
            const double side_value = glm::dot(cc, u) / glm::length(cc);
            const glm::dvec4 reflected = reflection * (glm::dmat4(pair.inverse()) * u);
            if (side_value < -delta) {
                ++seen_in_mirror;
                CHECK(clip_inside(mm * reflected, c.depth, -tol));
            } else if (side_value > delta) {
                ++in_front;
                CHECK_FALSE(clip_inside(mm * reflected, c.depth, -tol));
            }
        }
        const Plane<T> near = frustum::planes(*m).near;
        const Plane<T> expected = sign > 0 ? plane.normalized() : plane.normalized().flipped();
        CHECK(near == close_abs(expected, loose<T>() * (1 + std::abs(double(plane.offset())))));
    });
    CHECK(seen_in_mirror > 5000);
    CHECK(in_front > 5000);
    CHECK_MESSAGE(negated == 0, negated, " of 1000 mirror pairs came back negated (w < 0 inside)");
}

TEST_CASE_TEMPLATE("mirror of an infinite-far camera works", T, float, double) {
    for_each_depth_range([&](DepthRange depth) {
        const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, infinite_far, depth);
        REQUIRE(base.ok());
        // Tilted mirror z = -5 + 0.2 x, facing the eye.
        const Plane<T> plane = Plane<T>(T(-0.2), 0, 1, 5).normalized();
        const auto m = frustum::mirror(*base, plane);
        REQUIRE_MESSAGE(m.ok(), m.error());
        CHECK(inverse_residual(*m) <= 64 * eps<T>());
        // (0, 0, -50) is behind the mirror and in view: its reflection shows.
        const glm::dmat4 reflection = frustum::reflection_matrix(Plane<double>(glm::dvec4(plane.abcd)));
        const glm::dvec4 shown = glm::dmat4(m->matrix()) * (reflection * glm::dvec4(0, 0, -50, 1));
        CHECK(clip_inside(shown, depth));
    });
}

TEST_CASE_TEMPLATE("mirror errors", T, float, double) {
    const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), DepthRange::ZeroToOne);
    REQUIRE(base.ok());
    // The eye behind the mirror (c(0) = -5 < 0).
    const auto behind = frustum::mirror(*base, Plane<T>(0, 0, -1, -5));
    REQUIRE_FALSE(behind.ok());
    CHECK(behind.error().rfind("frustum::mirror(): ", 0) == 0);
    CHECK(behind.error().find("eye") != std::string::npos);
    // A zero normal: exact text.
    const auto zero = frustum::mirror(*base, Plane<T>(0, 0, 0, 1));
    REQUIRE_FALSE(zero.ok());
    CHECK(zero.error() == "frustum::mirror(): plane normal must be non-zero and finite, got (0, 0, 0, 1)");
    // A mirror through the eye.
    const auto through = frustum::mirror(*base, Plane<T>(0, 1, 0, 0));
    REQUIRE_FALSE(through.ok());
    CHECK(through.error().find("must not pass through the eye") != std::string::npos);
    // A mirror behind the camera, facing it (z = 5): nothing of it in view.
    const auto unseen = frustum::mirror(*base, Plane<T>(0, 0, -1, 5));
    REQUIRE_FALSE(unseen.ok());
    CHECK(unseen.error().find("leaves no part of the frustum visible") != std::string::npos);
    // A mirror beyond the far plane (z = -20, facing the eye).
    const auto too_far = frustum::mirror(*base, Plane<T>(0, 0, 1, 20));
    REQUIRE_FALSE(too_far.ok());
    CHECK(too_far.error().find("leaves no part of the frustum visible") != std::string::npos);
    // NaN in the plane.
    const auto nan = frustum::mirror(*base, Plane<T>(0, std::numeric_limits<T>::quiet_NaN(), 1, 5));
    REQUIRE_FALSE(nan.ok());
    CHECK(nan.error().find("plane must be finite") != std::string::npos);
}

} // TEST_SUITE
