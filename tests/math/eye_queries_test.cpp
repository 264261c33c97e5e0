// The answers queries.hpp gives about a camera's eye: eye_point,
// near_distance, far_distance and near_plane_frame, on the 90-degree
// landmark at E = (1, 2, 3) looking along +x (near 1, far 10: both known
// by hand), on an orthographic box (no finite eye) and on random cameras.
// Also Plane::at / through / facing, the plane builders they rely on.
#include "support.hpp"

using namespace mtest;
using frustum::DepthRange;
using frustum::infinite_far;

namespace {

template <class T>
MatrixPair<T> landmark(std::optional<T> far, DepthRange depth) {
    const auto projection = frustum::perspective<T>(T(pi / 2), T(1), T(1), far, depth);
    const auto view = frustum::look_at<T>({1, 2, 3}, {4, 2, 3}, {0, 1, 0});
    REQUIRE((projection.ok() && view.ok()));
    return frustum::compose(*projection, *view);
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("eye_point, near_distance, far_distance of the landmark, by hand", T, float, double) {
    const double tol = loose<T>() * 20;
    for (const DepthRange depth : all_depth_ranges) {
        INFO("depth=", frustum::to_string(depth));
        const auto camera = landmark<T>(T(10), depth);
        const auto eye = frustum::eye_point(camera);
        REQUIRE(eye.has_value());
        CHECK(*eye == close_abs(Vec3<T>(1, 2, 3), tol));
        const auto near_m = frustum::near_distance(camera);
        const auto far_m = frustum::far_distance(camera);
        REQUIRE((near_m.ok() && far_m.ok()));
        CHECK(std::abs(double(*near_m) - 1) <= tol);
        CHECK(std::abs(double(*far_m) - 10) <= tol);
        // The near-plane frame: centre E + (1, 0, 0), x along world +z
        // (look_at's side axis), y along +y, half sizes 1 (90 degrees).
        const auto frame = frustum::near_plane_frame(camera);
        REQUIRE(frame.ok());
        CHECK(frame->center == close_abs(Vec3<T>(2, 2, 3), tol));
        CHECK(frame->x_axis == close_abs(Vec3<T>(0, 0, 1), tol));
        CHECK(frame->y_axis == close_abs(Vec3<T>(0, 1, 0), tol));
        CHECK(frame->forward() == close_abs(Vec3<T>(1, 0, 0), tol));
        CHECK(std::abs(double(frame->half_width_m) - 1) <= tol);
        CHECK(frame->eye == *eye); // one eye, from eye_point
    }
}

TEST_CASE_TEMPLATE("far_distance refuses an infinite far plane; every query refuses an orthographic box", T, float,
                   double) {
    const auto infinite = landmark<T>(infinite_far, DepthRange::ZeroToOne);
    CHECK(frustum::near_distance(infinite).ok());
    CHECK(frustum::far_distance(infinite).error() == "frustum::far_distance(): needs a finite far plane");

    const auto box = frustum::orthographic<T>(-1, 1, -1, 1, T(0.5), 10, DepthRange::ZeroToOne);
    REQUIRE(box.ok());
    CHECK_FALSE(frustum::eye_point(*box).has_value());
    CHECK(frustum::near_distance(*box).error() == "frustum::near_distance(): needs a perspective camera (finite eye)");
    CHECK(frustum::far_distance(*box).error() == "frustum::far_distance(): needs a perspective camera (finite eye)");
    CHECK(frustum::near_plane_frame(*box).error() ==
          "frustum::near_plane_frame(): needs a perspective camera (finite eye)");
}

TEST_CASE("eye_point is the eye of random cameras; near/far distances are the specs' near and far") {
    Random rng(1501);
    CameraOptions perspective_only;
    perspective_only.orthographic = false;
    for (int i = 0; i < 200; ++i) {
        const CameraSpec spec = random_camera(rng, perspective_only);
        if (spec.kind == Kind::Orthographic) {
            continue;
        }
        const auto camera = make<double>(spec);
        INFO(spec.text());
        const auto eye = frustum::eye_point(camera);
        REQUIRE(eye.has_value());
        CHECK(*eye == close_abs(spec.eye, 1e-9 * (1 + glm::length(spec.eye))));
        CHECK(std::abs(frustum::near_distance(camera).value() - spec.near_m) <= 1e-9 * spec.far_m);
        const auto far_m = frustum::far_distance(camera);
        CHECK(far_m.ok() == !spec.infinite);
        if (!spec.infinite) {
            CHECK(std::abs(*far_m - spec.far_m) <= 1e-9 * spec.far_m);
        }
    }
}

TEST_CASE_TEMPLATE("Plane::through, at and facing", T, float, double) {
    // Counter-clockwise seen from +z: normal (b - a) x (c - a) = (0, 0, 1) * 1.
    const auto p = Plane<T>::through({0, 0, 2}, {1, 0, 2}, {0, 1, 2});
    CHECK(p.abcd == Vec4<T>(0, 0, 1, -2));
    CHECK(p.distance({5, 5, 3}) == T(1));
    CHECK(Plane<T>::at({0, 0, 3}, {0, 0, 2}).abcd == Vec4<T>(0, 0, 3, -6));
    CHECK(p.facing({0, 0, 3}).abcd == p.abcd);
    CHECK(p.facing({0, 0, 1}).abcd == p.flipped().abcd);
    CHECK(p.facing({7, -3, 2}).abcd == p.abcd); // on the plane: kept
    // Collinear points: a zero normal (no plane).
    CHECK(Plane<T>::through({0, 0, 0}, {1, 1, 1}, {2, 2, 2}).normal() == Vec3<T>(0));
}

} // TEST_SUITE
