// Rigid transforms (rigid.hpp): exact inverse and composition, frames,
// planes from a point and a normal, and planes carried by a rigid motion.
#include "support.hpp"

using namespace mtest;
using frustum::Frame;
using frustum::RigidTransform;

namespace {

template <class T>
RigidTransform<T> random_rigid(Random& rng) {
    const glm::dvec3 eye = rng.in_box(10);
    const glm::dvec3 dir = rng.unit_vector();
    glm::dvec3 up;
    do {
        up = rng.unit_vector();
    } while (glm::length(glm::cross(dir, up)) < 0.2);
    const auto view = frustum::look_at<T>(Vec3<T>(eye), Vec3<T>(eye + dir), Vec3<T>(up));
    REQUIRE_MESSAGE(view.ok(), view.error());
    return *view;
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("rigid: inverse() swaps matrix and inverse; a * b composes both, no inversion", T, float, double) {
    Random rng(7001);
    for (int i = 0; i < 200; ++i) {
        const RigidTransform<T> a = random_rigid<T>(rng), b = random_rigid<T>(rng);
        const RigidTransform<T> a_inv = frustum::inverse(a);
        CHECK(a_inv.matrix == a.inverse);
        CHECK(a_inv.inverse == a.matrix);
        const RigidTransform<T> ab = a * b;
        CHECK(inverse_residual(ab.matrix, ab.inverse) <= 64 * eps<T>());
        const Vec4<T> p(Vec3<T>(rng.in_box(5)), T(1));
        // (a * b) p = a (b p) = then(b, a) p, and the inverse undoes it.
        CHECK(ab.matrix * p == close_abs(a.matrix * (b.matrix * p), 64 * eps<T>() * 20));
        CHECK(frustum::then(b, a).matrix * p == close_abs(a.matrix * (b.matrix * p), 64 * eps<T>() * 20));
        CHECK(ab.inverse * (a.matrix * (b.matrix * p)) == close_abs(p, 64 * eps<T>() * 20));
    }
}

TEST_CASE_TEMPLATE("rigid: a frame maps local (1,0,0), (0,1,0), (0,0,1), origin to x, y, x × y, origin", T, float,
                   double) {
    // x = (0, 0, -1), y = (0, 1, 0): n = x × y = (1, 0, 0).
    const Frame<T> f{{10, 1, -3}, {0, 0, -1}, {0, 1, 0}};
    const auto world = frustum::frame_to_world(f, "portal", "exit");
    REQUIRE_MESSAGE(world.ok(), world.error());
    CHECK(world->matrix * Vec4<T>(1, 0, 0, 0) == Vec4<T>(0, 0, -1, 0));
    CHECK(world->matrix * Vec4<T>(0, 1, 0, 0) == Vec4<T>(0, 1, 0, 0));
    CHECK(world->matrix * Vec4<T>(0, 0, 1, 0) == Vec4<T>(1, 0, 0, 0));
    CHECK(world->matrix * Vec4<T>(0, 0, 0, 1) == Vec4<T>(10, 1, -3, 1));
    CHECK(inverse_residual(world->matrix, world->inverse) <= 32 * eps<T>());
}

TEST_CASE_TEMPLATE("rigid: frame errors name the frame and the tolerance", T, float, double) {
    CHECK(frustum::frame_to_world(Frame<T>{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}}, "portal", "entry").error() ==
          "frustum::portal(): entry frame axes x and y must be unit length and orthogonal (each within 1e-6), "
          "got |x|=2 |y|=1 x.y=0");
    CHECK(frustum::frame_to_world(Frame<T>{{0, 0, 0}, {1, 0, 0}, {T(0.6), T(0.8), 0}}, "portal", "exit").error()
              .find("frustum::portal(): exit frame axes x and y must be unit length and orthogonal (each within "
                    "1e-6), got |x|=1 |y|=") == 0);
    const T inf = std::numeric_limits<T>::infinity();
    CHECK(frustum::frame_to_world(Frame<T>{{inf, 0, 0}, {1, 0, 0}, {0, 1, 0}}, "portal", "entry").error() ==
          "frustum::portal(): entry frame must be finite, got origin=(inf, 0, 0) x=(1, 0, 0) y=(0, 1, 0)");
}

TEST_CASE_TEMPLATE("rigid: plane_from_point_normal is unit, through the point, positive along the normal", T, float,
                   double) {
    const auto p = frustum::plane_from_point_normal<T>(Vec3<T>(0, 0, 2), Vec3<T>(0, 0, -5));
    REQUIRE_MESSAGE(p.ok(), p.error());
    CHECK(p->abcd == Vec4<T>(0, 0, -1, 2));
    Random rng(7002);
    for (int i = 0; i < 100; ++i) {
        const Vec3<T> point(rng.in_box(10)), normal(rng.in_box(3) * (i % 2 ? 1e-30 : 1e30));
        const auto plane = frustum::plane_from_point_normal(point, normal);
        REQUIRE_MESSAGE(plane.ok(), plane.error());
        CHECK(std::abs(double(glm::length(plane->normal())) - 1) <= 4 * eps<T>());
        CHECK(std::abs(double(plane->distance(point))) <= 64 * eps<T>() * 10);
        CHECK(plane->distance(point + plane->normal()) > T(0));
    }
    CHECK(frustum::plane_from_point_normal<T>(Vec3<T>(1, 2, 3), Vec3<T>(0)).error() ==
          "frustum::plane_from_point_normal(): normal must be non-zero, got normal=(0, 0, 0)");
    CHECK(frustum::plane_from_point_normal<T>(Vec3<T>(1, std::numeric_limits<T>::quiet_NaN(), 3), Vec3<T>(0, 1, 0))
              .error() ==
          "frustum::plane_from_point_normal(): point and normal must be finite, got point=(1, nan, 3) "
          "normal=(0, 1, 0)");
}

TEST_CASE_TEMPLATE("rigid: transformed(plane, A) keeps every signed distance: c'(A p) = c(p)", T, float, double) {
    Random rng(7003);
    for (int i = 0; i < 200; ++i) {
        const RigidTransform<T> a = random_rigid<T>(rng);
        const auto plane = frustum::plane_from_point_normal(Vec3<T>(rng.in_box(10)), Vec3<T>(rng.unit_vector()));
        REQUIRE(plane.ok());
        const Plane<T> carried = frustum::transformed(*plane, a);
        CHECK(std::abs(double(glm::length(carried.normal())) - 1) <= 16 * eps<T>());
        for (int k = 0; k < 4; ++k) {
            const Vec3<T> p(rng.in_box(10));
            const Vec3<T> moved(a.matrix * Vec4<T>(p, T(1)));
            CHECK(std::abs(double(carried.distance(moved) - plane->distance(p))) <= 64 * eps<T>() * 40);
        }
    }
}

} // TEST_SUITE
