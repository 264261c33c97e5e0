// portal(pair, entry, exit) (portal.hpp): T = F_entry H F_exit^-1, M T,
// then clip_oblique by the exit plane; analytic inverse.
#include "support.hpp"

using namespace mtest;
using frustum::Frame;

namespace {

// Camera at (0, 1, 5) looking at (0, 1, 0); 60 degrees, square, 0.1..100.
template <class T>
MatrixPair<T> camera(DepthRange depth = DepthRange::ZeroToOne) {
    const auto p = frustum::perspective<T>(T(pi / 3), T(1), T(0.1), T(100), depth);
    const auto v = frustum::look_at<T>(Vec3<T>(0, 1, 5), Vec3<T>(0, 1, 0), Vec3<T>(0, 1, 0));
    REQUIRE(p.ok());
    REQUIRE(v.ok());
    return frustum::compose(*p, *v);
}

// Entry in the plane z = 0 facing +z (the camera); exit at (10, 1, -3)
// facing +x: x = (0, 0, -1), y = (0, 1, 0), n = (1, 0, 0).
template <class T>
Frame<T> entry_frame() {
    return {{0, 1, 0}, {1, 0, 0}, {0, 1, 0}};
}
template <class T>
Frame<T> exit_frame() {
    return {{10, 1, -3}, {0, 0, -1}, {0, 1, 0}};
}

// A random frame whose front faces `eye`, through `origin`.
template <class T>
Frame<T> facing(Random& rng, const glm::dvec3& origin, const glm::dvec3& eye) {
    glm::dvec3 n = rng.unit_vector();
    if (glm::dot(n, eye - origin) < 0) n = -n;
    if (std::abs(glm::dot(n, glm::normalize(eye - origin))) < 0.2) n = glm::normalize(eye - origin);
    glm::dvec3 helper;
    do {
        helper = rng.unit_vector();
    } while (glm::length(glm::cross(helper, n)) < 0.3);
    const glm::dvec3 x = glm::normalize(glm::cross(helper, n));
    const glm::dvec3 y = glm::cross(n, x);
    return {Vec3<T>(origin), Vec3<T>(x), Vec3<T>(y)};
}

template <class T>
Frame<T> random_frame(Random& rng) {
    return facing<T>(rng, rng.in_box(20), rng.in_box(20) + glm::dvec3(50, 0, 0));
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("portal: literal case, virtual eye behind the exit, near plane = exit plane", T, float, double) {
    for (const DepthRange depth : all_depth_ranges) {
        const MatrixPair<T> pair = camera<T>(depth);
        const auto through = frustum::portal(pair, entry_frame<T>(), exit_frame<T>());
        REQUIRE_MESSAGE(through.ok(), through.error());
        // Eye (0, 1, 5) is (0, 0, 5) in the entry frame; H gives (0, 0, -5),
        // i.e. 5 behind the exit: (10, 1, -3) - 5 (1, 0, 0) = (5, 1, -3).
        const auto k = frustum::key_points(*through);
        CHECK(frustum::to_point(k.eye, T(1e-6)) == close_abs(Vec4<T>(5, 1, -3, 1), loose<T>() * 10));
        // The near plane is the exit plane, positive on its front: x - 10 >= 0.
        const auto planes = frustum::planes(*through);
        CHECK(planes.near.abcd == close_abs(Vec4<T>(1, 0, 0, -10), loose<T>() * 10));
        CHECK_FALSE(through->flips_winding()); // H is a rotation
        CHECK(inverse_residual(*through) <= 64 * eps<T>());
        // A point 3 in front of the exit, straight ahead of the virtual
        // camera, is where the entry's centre was: the screen centre.
        const Vec4<T> c = through->matrix() * Vec4<T>(13, 1, -3, 1);
        CHECK(std::abs(double(c.x / c.w)) <= loose<T>());
        CHECK(std::abs(double(c.y / c.w)) <= loose<T>());
    }
}

TEST_CASE_TEMPLATE("portal: x, y, w of M' p equal those of M (T p); the inverse is T^-1 M^-1 (no inversion)", T,
                   float, double) {
    Random rng(7101);
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
        CameraOptions options;
        options.orthographic = false;
        const CameraSpec spec = random_camera(rng, options);
        const MatrixPair<T> pair = make<T>(spec);
        const glm::dvec4 inside = glm::dmat4(pair.inverse()) * random_clip_point(rng, spec.depth, 0.2);
        const glm::dvec3 eye = glm::dvec3(frustum::to_point(glm::dvec4(pair.inverse()[2]), 1e-12));
        const Frame<T> entry = facing<T>(rng, glm::dvec3(inside) / inside.w, eye);
        const Frame<T> exit = random_frame<T>(rng);
        const auto through = frustum::portal(pair, entry, exit);
        INFO("camera: ", spec.text());
        REQUIRE_MESSAGE(through.ok(), through.error());
        const auto carry = frustum::portal_transform(entry, exit);
        REQUIRE(carry.ok());
        for (int k = 0; k < 4; ++k) {
            const Vec4<T> p(Vec3<T>(rng.in_box(20)), T(1));
            const Vec4<T> direct = pair.matrix() * (carry->matrix * p);
            const Vec4<T> ported = through->matrix() * p;
            const double scale = max_abs(glm::dvec4(direct)) + 1;
            CHECK(std::abs(double(ported.x - direct.x)) <= loose<T>() * 10 * scale);
            CHECK(std::abs(double(ported.y - direct.y)) <= loose<T>() * 10 * scale);
            CHECK(std::abs(double(ported.w - direct.w)) <= loose<T>() * 10 * scale);
        }
        // clip_oblique's own bound (mirror_test, oblique_clip_test), 4x in
        // double for the rigid carry before the clip: the worst of these 300
        // cases is 150 eps on aarch64 and armhf, whose libm draws other last
        // bits of the random cameras than x86-64's (make test-arm).
        CHECK(inverse_residual(*through) <= (sizeof(T) == 4 ? 1024 : 256) * eps<T>());
        ++checked;
    }
    CHECK(checked == 300);
}

TEST_CASE_TEMPLATE("portal: exit = entry turned about y is the identity carry, i.e. clip_oblique by the entry plane "
                   "flipped",
                   T, float, double) {
    const MatrixPair<T> pair = camera<T>();
    const Frame<T> entry{{0, 1, 1}, {1, 0, 0}, {0, 1, 0}};
    const Frame<T> turned{{0, 1, 1}, {-1, 0, 0}, {0, 1, 0}}; // F_entry H
    const auto through = frustum::portal(pair, entry, turned);
    const auto clipped = frustum::clip_oblique(pair, Plane<T>(0, 0, -1, 1)); // keep z <= 1
    REQUIRE_MESSAGE(through.ok(), through.error());
    REQUIRE_MESSAGE(clipped.ok(), clipped.error());
    CHECK(through->matrix() == close(clipped->matrix(), tight<T>()));
    CHECK(through->inverse() == close(clipped->inverse(), tight<T>()));
}

TEST_CASE_TEMPLATE("portal: a mirror is the special case F S F^-1 with S = diag(1, 1, -1, 1): eq. 16", T, float,
                   double) {
    Random rng(7102);
    for (int i = 0; i < 50; ++i) {
        const Frame<T> f = random_frame<T>(rng);
        const auto world = frustum::frame_to_world(f, "test", "mirror");
        REQUIRE(world.ok());
        Mat4<T> s(T(1));
        s[2][2] = T(-1);
        const Mat4<T> reflection = world->matrix * s * world->inverse;
        CHECK(reflection == close(frustum::reflection_matrix(frustum::frame_plane(f)), 64 * eps<T>() * 40));
    }
}

TEST_CASE_TEMPLATE("portal: errors, exact texts", T, float, double) {
    const MatrixPair<T> pair = camera<T>();
    // Eye (0, 1, 5) behind an entry facing -z.
    const Frame<T> back{{0, 1, 0}, {-1, 0, 0}, {0, 1, 0}};
    CHECK(frustum::portal(pair, back, exit_frame<T>()).error() ==
          "frustum::portal(): the eye must be on the entry portal's front (positive) side, got "
          "entry_plane=(0, 0, -1, 0) eye_distance=-5");
    // The entry's plane through the eye (x = 0, facing +x).
    const Frame<T> through_eye{{0, 1, 0}, {0, 0, -1}, {0, 1, 0}};
    CHECK(frustum::portal(pair, through_eye, exit_frame<T>()).error() ==
          "frustum::portal(): the eye must not lie in the entry portal's plane, got entry_plane=(1, 0, 0, 0) "
          "eye_distance=0");
    CHECK(frustum::portal(pair, Frame<T>{{0, 1, 0}, {1, 0, 0}, {0, 2, 0}}, exit_frame<T>()).error() ==
          "frustum::portal(): entry frame axes x and y must be unit length and orthogonal (each within 1e-6), "
          "got |x|=1 |y|=2 x.y=0");
    CHECK(frustum::portal(pair, entry_frame<T>(), Frame<T>{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}}).error() ==
          "frustum::portal(): exit frame axes x and y must be unit length and orthogonal (each within 1e-6), "
          "got |x|=1 |y|=1 x.y=1");
    // An entry beyond the far plane (z = -200, facing the eye): the whole
    // frustum is in front of it, nothing is seen through it.
    const Frame<T> too_close{{0, 1, -200}, {1, 0, 0}, {0, 1, 0}};
    CHECK(frustum::portal(pair, too_close, exit_frame<T>()).error().rfind(
              "frustum::portal(): frustum::clip_oblique(): clip plane leaves no part of the frustum visible", 0) ==
          0);
}

} // TEST_SUITE
