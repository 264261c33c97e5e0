// screen_projection (Kooima's generalized perspective, screen_projection.hpp)
// and mirror_rectangle(..., MirrorFit::Exact) as its special case.
#include "support.hpp"

using namespace mtest;

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("screen_projection: a centred screen is off_axis through the screen scaled to the near plane", T,
                   float, double) {
    // Screen z = -2, x, y in [-1, 1], eye at the origin: l, r, b, t = -+1 * n / 2.
    for (const DepthRange depth : all_depth_ranges) {
        const auto s = frustum::screen_projection<T>({-1, -1, -2}, {1, -1, -2}, {-1, 1, -2}, {0, 0, 0}, T(0.5),
                                                     T(30), depth);
        const auto o = frustum::off_axis<T>(T(-0.25), T(0.25), T(-0.25), T(0.25), T(0.5), T(30), depth);
        REQUIRE_MESSAGE(s.ok(), s.error());
        REQUIRE(o.ok());
        CHECK(s->matrix() == close(o->matrix(), tight<T>()));
        CHECK(s->inverse() == close(o->inverse(), tight<T>()));
    }
    // Moving eye and screen together by (3, 4, 5) moves the frustum.
    const auto moved = frustum::screen_projection<T>({2, 3, 3}, {4, 3, 3}, {2, 5, 3}, {3, 4, 5}, T(0.5),
                                                     std::nullopt, DepthRange::ZeroToOne);
    REQUIRE_MESSAGE(moved.ok(), moved.error());
    const Vec4<T> c = moved->matrix() * Vec4<T>(4, 5, 3, 1); // upper-right screen corner
    CHECK(c.x / c.w == doctest::Approx(1).epsilon(1e-5));
    CHECK(c.y / c.w == doctest::Approx(1).epsilon(1e-5));
}

TEST_CASE_TEMPLATE("screen_projection == mirror_rectangle(Exact) on 500 random mirrors", T, float, double) {
    // Tolerance: both build the same off_axis window and the same rotation
    // from the same corners in a different order of operations, so they
    // agree to rounding amplified by the camera's conditioning (eye up to
    // 6 from a mirror up to 5 wide, far/near up to 50): relative 4e3 eps of
    // the largest entry for the matrix (measured worst: 1100 eps, float and double),
    // column-wise relative 1e4 eps for the inverse (its columns are key
    // points of very different sizes).
    Random rng(7401);
    for (int i = 0; i < 500; ++i) {
        const glm::dvec3 corner = rng.in_box(10);
        const glm::dvec3 a1 = rng.unit_vector() * rng.uniform(0.5, 5);
        glm::dvec3 a2 = glm::cross(a1, rng.unit_vector());
        if (glm::length(a2) < 1e-3) continue;
        a2 = glm::normalize(a2) * rng.uniform(0.5, 5);
        const glm::dvec3 normal = glm::normalize(glm::cross(a1, a2));
        const glm::dvec3 centre = corner + (a1 + a2) / 2.0;
        const double side = rng.coin() ? 1 : -1;
        const glm::dvec3 eye = centre + rng.in_box(4) + normal * side * rng.uniform(0.5, 6);
        const double distance = glm::dot(normal, eye - corner);
        const glm::dvec3 reflected = eye - 2 * distance * normal;
        const T far_m = T(std::abs(distance) * rng.uniform(3, 50));
        const DepthRange depth = rng.depth();
        const frustum::Rectangle<T> rect{Vec3<T>(corner), Vec3<T>(a1), Vec3<T>(a2)};
        const auto exact = frustum::mirror_rectangle(rect, Vec3<T>(eye), far_m, frustum::MirrorFit::Exact, depth);
        REQUIRE_MESSAGE(exact.ok(), exact.error());
        // Exact's basis: k = normal towards O', up j = unit(a1), right i = j x k.
        const glm::dvec3 k = distance > 0 ? -normal : normal;
        const glm::dvec3 right = glm::cross(glm::normalize(a1), k);
        const bool a2_right = glm::dot(a2, right) > 0;
        const glm::dvec3 ll = a2_right ? corner : corner + a2;
        const glm::dvec3 lr = a2_right ? corner + a2 : corner;
        const glm::dvec3 ul = ll + a1;
        const auto screen = frustum::screen_projection(Vec3<T>(ll), Vec3<T>(lr), Vec3<T>(ul), Vec3<T>(reflected),
                                                       T(std::abs(distance)), std::optional<T>(far_m), depth);
        INFO("case ", i, " eye=", vec_text(eye), " corner=", vec_text(corner));
        REQUIRE_MESSAGE(screen.ok(), screen.error());
        CHECK(screen->matrix() == close(exact->matrix(), 4e3 * eps<T>()));
        CHECK(column_relative_diff(screen->inverse(), exact->inverse()) <= 1e4 * eps<T>());
    }
}

TEST_CASE_TEMPLATE("screen_projection: errors, exact texts", T, float, double) {
    const Vec3<T> ll(-1, -1, -2), lr(1, -1, -2), ul(-1, 1, -2);
    CHECK(frustum::screen_projection<T>(ll, lr, ul, {0, 0, -5}, T(0.5), T(30), DepthRange::ZeroToOne).error() ==
          "frustum::screen_projection(): eye must be in front of the screen (the side (lower_right - lower_left) x "
          "(upper_left - lower_left) points to), got eye_distance=-3");
    CHECK(frustum::screen_projection<T>(ll, lr, ul, {3, 0, -2}, T(0.5), T(30), DepthRange::ZeroToOne).error() ==
          "frustum::screen_projection(): eye must not lie in the screen's plane, got eye_distance=0");
    CHECK(frustum::screen_projection<T>(ll, lr, {0, 1, -2}, {0, 0, 0}, T(0.5), T(30), DepthRange::ZeroToOne)
              .error()
              .rfind("frustum::screen_projection(): screen edges lower_right - lower_left and upper_left - "
                     "lower_left must be perpendicular (|cos| <= tolerance), got cos=0.44721",
                     0) == 0);
    CHECK(frustum::screen_projection<T>(ll, ll, ul, {0, 0, 0}, T(0.5), T(30), DepthRange::ZeroToOne).error() ==
          "frustum::screen_projection(): screen edges must be non-zero and finite, got width=0 height=2");
    CHECK(frustum::screen_projection<T>(ll, lr, ul, {0, 0, 0}, T(0), T(30), DepthRange::ZeroToOne).error() ==
          "frustum::screen_projection(): near must be finite and > 0, got near=0");
    CHECK(frustum::screen_projection<T>(ll, lr, ul, {0, 0, 0}, T(0.5), T(0.25), DepthRange::ZeroToOne)
              .error()
              .rfind("frustum::screen_projection(): frustum::off_axis(): ", 0) == 0);
}

} // TEST_SUITE
