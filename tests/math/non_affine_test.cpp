// Paper §6: non-affine frustums given by six planes.
#include "support.hpp"

using namespace frustum;

namespace {

// A box-like non-affine frustum: the left and right planes are tilted about
// different axes so no 4x4 matrix maps it (its side planes do not meet in
// one point).
NonAffineFrustum<double> twisted() {
    const Plane<double> left(-1.0, 0.1, 0.0, -1.0);   // outward normals
    const Plane<double> right(1.0, 0.0, 0.2, -1.0);
    const Plane<double> bottom(0.0, -1.0, 0.0, -1.0);
    const Plane<double> top(0.1, 1.0, 0.0, -1.0);
    const Plane<double> near(0.0, 0.0, 1.0, 1.0);     // z <= -1
    const Plane<double> far(0.0, 0.2, -1.0, -10.0);   // z >= -10 (tilted)
    return *NonAffineFrustum<double>::from_planes(left, right, bottom, top, near, far, glm::dvec3(0, 0, -5),
                                                  DepthRange::ZeroToOne);
}

} // namespace

TEST_SUITE("math") {

TEST_CASE("eq. 36 maps each plane to its face of the clip cube") {
    const auto f = twisted();
    // A point on the left plane x = -1 + 0.1 y (normalized form): u = 0 -> x_clip = -1.
    const glm::dvec3 on_left(-1.0, 0.0, -5.0);
    const auto c = f.to_clip(on_left, 1e-9);
    REQUIRE(c.has_value());
    CHECK(c->x == doctest::Approx(-1.0).epsilon(mtest::tight<double>()));
    const glm::dvec3 on_near(0.0, 0.0, -1.0);
    CHECK(f.to_clip(on_near, 1e-9)->z == doctest::Approx(0.0).epsilon(mtest::tight<double>()));
    const glm::dvec3 on_top(0.0, 1.0, -5.0);
    CHECK(f.to_clip(on_top, 1e-9)->y == doctest::Approx(1.0).epsilon(mtest::tight<double>()));
    // Inside points land inside the cube.
    for (double x : {-0.5, 0.0, 0.5})
        for (double z : {-2.0, -5.0, -9.0}) {
            const auto p = f.to_clip(glm::dvec3(x, 0.2, z), 1e-9);
            REQUIRE(p.has_value());
            CHECK(std::abs(p->x) < 1.0);
            CHECK(std::abs(p->y) < 1.0);
            CHECK(p->z > 0.0);
            CHECK(p->z < 1.0);
        }
}

TEST_CASE("the zero-denominator set exists and to_clip refuses it") {
    const auto f = twisted();
    // Search along the axis from inside to far behind the near plane for a
    // sign change of d_l + d_r (about z = +10 for these planes: a triangle
    // reaching behind the viewer): there the mapping blows up.
    bool found = false;
    glm::dvec3 previous(0.0, 0.0, -5.0);
    for (int i = 1; i <= 4000 && !found; ++i) {
        const glm::dvec3 p(0.0, 0.0, -5.0 + 35.0 * i / 4000.0);
        if (f.denominators(previous).x * f.denominators(p).x <= 0.0) {
            found = true;
            // Near the root |d_l + d_r| < guard: refused on both sides.
            const glm::dvec3 middle = (p + previous) / 2.0;
            CHECK(std::abs(f.denominators(middle).x) < 1e-2);
            CHECK_FALSE(f.to_clip(p, 1e-2).has_value());
            CHECK_FALSE(f.to_clip(middle, 1e-2).has_value());
            CHECK(f.to_clip(glm::dvec3(0.0, 0.0, -5.0), 1e-2).has_value());
        }
        previous = p;
    }
    CHECK(found);
}

TEST_CASE("an affine frustum through eq. 36 keeps inside inside") {
    const auto projection = perspective(1.0, 1.0, 1.0, std::optional<double>(10.0), DepthRange::ZeroToOne);
    const auto p = planes(*projection);
    const auto f = NonAffineFrustum<double>::from_planes(p.left.flipped(), p.right.flipped(), p.bottom.flipped(),
                                                         p.top.flipped(), p.near.flipped(), p.far->flipped(),
                                                         glm::dvec3(0, 0, -5), DepthRange::MinusOneToOne);
    REQUIRE(f.ok());
    const auto centre = f->to_clip(glm::dvec3(0, 0, -5), 1e-9);
    CHECK(centre->x == doctest::Approx(0.0).epsilon(mtest::tight<double>()));
    CHECK(centre->y == doctest::Approx(0.0).epsilon(mtest::tight<double>()));
    // eq. 36 is linear in distances: the middle of near and far maps to z = 0 of [-1, 1].
    CHECK(f->to_clip(glm::dvec3(0, 0, -5.5), 1e-9)->z == doctest::Approx(0.0).epsilon(mtest::tight<double>()));
}

TEST_CASE("from_planes rejects an inside point outside a plane, and bad planes") {
    const Plane<double> unit_x(1, 0, 0, -1);
    const auto outside = NonAffineFrustum<double>::from_planes(unit_x, unit_x, unit_x, unit_x, unit_x, unit_x,
                                                               glm::dvec3(5, 0, 0), DepthRange::ZeroToOne);
    CHECK_FALSE(outside.ok());
    CHECK(outside.error().find("inner") != std::string::npos);
    const Plane<double> zero(0, 0, 0, 1);
    const auto degenerate = NonAffineFrustum<double>::from_planes(zero, unit_x, unit_x, unit_x, unit_x, unit_x,
                                                                  glm::dvec3(0, 0, 0), DepthRange::ZeroToOne);
    CHECK_FALSE(degenerate.ok());
    CHECK(degenerate.error().find("left plane") != std::string::npos);
}

} // TEST_SUITE
