// Key points (paper §3.2, eq. 5-8; queries.hpp): corners C1..C8, centre D,
// eye O and vanishing points O1, O2 read from the columns of M^-1; then the
// answers built on them (eye_point, near/far_distance, near_plane_frame).
// First known cameras with landmarks worked out by hand, then properties
// over random cameras.
#include "support.hpp"

using namespace mtest;
using frustum::DepthRange;
using frustum::infinite_far;

namespace {

template <class T>
Vec4<T> point(const Vec4<T>& h) {
    return frustum::to_point(h, frustum::infinity_tolerance<T>());
}

// The landmark camera (90 degrees, aspect 1, near 1, far 10) placed at
// E = (1, 2, 3) looking along +x with y up. look_at's side axis is
// forward x up = (1,0,0) x (0,1,0) = (0,0,1), so an eye-space point
// (x, y, z) is the world point E + x (0,0,1) + y (0,1,0) - z (1,0,0).
template <class T>
MatrixPair<T> landmark_at_e(std::optional<T> far, DepthRange depth) {
    const auto projection = frustum::perspective<T>(T(pi / 2), T(1), T(1), far, depth);
    const auto view = frustum::look_at<T>({1, 2, 3}, {4, 2, 3}, {0, 1, 0});
    REQUIRE((projection.ok() && view.ok()));
    return frustum::compose(*projection, *view);
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("key points of the 90-degree landmark at E = (1, 2, 3) looking along +x", T, float, double) {
    // Eye-space corners: near (+-1, +-1, -1), far (+-10, +-10, -10) in eq. 8
    // order (x, y) = (1,1), (-1,1), (-1,-1), (1,-1); mapped as above:
    const Vec4<T> expected[8] = {{2, 3, 4, 1},   {2, 3, 2, 1},   {2, 1, 2, 1},   {2, 1, 4, 1},
                                 {11, 12, 13, 1}, {11, 12, -7, 1}, {11, -8, -7, 1}, {11, -8, 13, 1}};
    // Centre D: clip z = z_mid is eye depth 2nf/(n + f) = 20/11 in EVERY
    // depth range (the ranges differ by an affine map of clip z that keeps
    // the middle in the middle): D = E + 20/11 (1, 0, 0).
    const Vec4<T> centre(T(1 + 20.0 / 11), 2, 3, 1);
    // Corners and eye are 10..20 from the origin: loose() absolute.
    const double tol = loose<T>() * 20;
    for_each_depth_range([&](DepthRange depth) {
        const auto k = frustum::key_points(landmark_at_e<T>(T(10), depth));
        for (int i = 0; i < 8; ++i) {
            CAPTURE(i);
            CHECK(point(k.corners[i]) == close_abs(expected[i], tol));
        }
        CHECK(point(k.center) == close_abs(centre, tol));
        // O = m2' is the eye (finite, w > 0 after the sign choice).
        CHECK(point(k.eye) == close_abs(Vec4<T>(1, 2, 3, 1), tol));
        CHECK(k.eye.w > 0);
        // A symmetric perspective's vanishing points are at infinity:
        // O2 along the camera's x axis (world +z), O1 along its y (world +y).
        CHECK(point(k.vanishing_x) == close_abs(Vec4<T>(0, 0, 1, 0), tol));
        CHECK(point(k.vanishing_y) == close_abs(Vec4<T>(0, 1, 0, 0), tol));
        CHECK(k.vanishing_x.w == 0);
        CHECK(k.vanishing_y.w == 0);
    });
}

TEST_CASE_TEMPLATE("key points of the landmark with an infinite far plane", T, float, double) {
    // Far corners become directions: eye-space (+-1, +-1, -1, 0) normalized,
    // i.e. world (1, +-1, +-1)/sqrt(3) with the mapping above.
    const T s = T(1 / std::sqrt(3.0));
    const Vec4<T> far_dirs[4] = {{s, s, s, 0}, {s, s, -s, 0}, {s, -s, -s, 0}, {s, -s, s, 0}};
    for_each_depth_range([&](DepthRange depth) {
        const auto k = frustum::key_points(landmark_at_e<T>(infinite_far, depth));
        CHECK(point(k.corners[0]) == close_abs(Vec4<T>(2, 3, 4, 1), loose<T>() * 10));
        for (int i = 4; i < 8; ++i) {
            CAPTURE(i);
            CHECK(point(k.corners[i]) == close_abs(far_dirs[i - 4], loose<T>()));
            CHECK(std::abs(k.corners[i].w) <= tight<T>() * glm::length(Vec3<T>(k.corners[i])));
        }
        // D: clip z_mid is eye depth 2n = 2 (the limit of 2nf/(n+f)).
        CHECK(point(k.center) == close_abs(Vec4<T>(3, 2, 3, 1), loose<T>() * 10));
    });
}

TEST_CASE_TEMPLATE("orthographic: the eye is at infinity, pointing away from the frustum", T, float, double) {
    // Box [-2, 2] x [-1, 1] x [-11, -1] seen from E = (1, 2, 3) along +x:
    // the projection direction is +x, the eye is the point at infinity
    // BEHIND the near plane: direction -x, w = 0.
    for_each_depth_range([&](DepthRange depth) {
        const auto projection = frustum::orthographic<T>(-2, 2, -1, 1, 1, 11, depth);
        const auto view = frustum::look_at<T>({1, 2, 3}, {4, 2, 3}, {0, 1, 0});
        REQUIRE((projection.ok() && view.ok()));
        const MatrixPair<T> pair = frustum::compose(*projection, *view);
        const auto k = frustum::key_points(pair);
        CHECK(k.eye.w == 0);
        CHECK(point(k.eye) == close_abs(Vec4<T>(-1, 0, 0, 0), tight<T>()));
        // The near plane x >= 2 is negative in the eye's direction.
        CHECK(frustum::planes(pair).near.evaluate(k.eye) < 0);
        // C1 = eye (2, 1, -1) -> (2, 3, 5); C7 = (-2, -1, -11) -> (12, 1, 1);
        // D = eye (0, 0, -6) -> (7, 2, 3).
        CHECK(point(k.corners[0]) == close_abs(Vec4<T>(2, 3, 5, 1), loose<T>() * 10));
        CHECK(point(k.corners[6]) == close_abs(Vec4<T>(12, 1, 1, 1), loose<T>() * 10));
        CHECK(point(k.center) == close_abs(Vec4<T>(7, 2, 3, 1), loose<T>() * 10));
        CHECK(frustum::validate(pair).valid());
    });
}

TEST_CASE_TEMPLATE("off-axis: vanishing points stay at infinity; an oblique near plane makes O2 finite", T, float,
                   double) {
    // O2 = m0' is where the planes m1 = 0 (Dy), m2 = 0 and m3 = 0 meet. For
    // any off_axis/perspective matrix m2 = 0 is a plane z = const and m3 = 0
    // is z = 0 (w = -z): parallel, so O1 and O2 are at infinity however far
    // the window is shifted.
    for_each_depth_range([&](DepthRange depth) {
        const auto shifted = frustum::off_axis<T>(T(0.5), T(3), T(-2), T(-0.25), T(1), T(10), depth);
        REQUIRE(shifted.ok());
        const auto k = frustum::key_points(*shifted);
        CHECK(k.vanishing_x.w == 0);
        CHECK(k.vanishing_y.w == 0);
        CHECK(point(k.vanishing_x) == close_abs(Vec4<T>(1, 0, 0, 0), tight<T>()));
        CHECK(point(k.vanishing_y) == close_abs(Vec4<T>(0, 1, 0, 0), tight<T>()));
    });
    // After an oblique clip the near plane is c, and m2 = (z_f - z_n) k c +
    // z_n m3, so {m2 = 0, m3 = 0} = {c = 0, z = 0}: a finite line when c is
    // tilted. Tilt about the eye's y axis: c = (0.6, 0, -0.8, -1.6), i.e.
    // z = 0.75 x - 2 (through (0, 0, -2), eye on its negative side:
    // c(0) = -1.6 < 0). With z = 0: x = 1.6/0.6 = 8/3; Dy is y = 0, so
    //   O2 = (8/3, 0, 0), finite, the same in every depth range,
    // while the line {c = 0, z = 0} runs along y and lies in Dx (x = 0 is
    // parallel to it): O1 stays at infinity, direction (0, +-1, 0).
    // O2 is on the near AND the far plane (both are combinations of m2, m3).
    for_each_depth_range([&](DepthRange depth) {
        const auto base = frustum::perspective<T>(T(pi / 2), T(1), T(1), T(10), depth);
        REQUIRE(base.ok());
        const auto clipped = frustum::clip_oblique(*base, Plane<T>(T(0.6), 0, T(-0.8), T(-1.6)));
        REQUIRE_MESSAGE(clipped.ok(), clipped.error());
        const auto k = frustum::key_points(*clipped);
        CHECK(point(k.vanishing_x) == close_abs(Vec4<T>(T(8.0 / 3), 0, 0, 1), 4 * loose<T>()));
        CHECK(k.vanishing_y.w == 0);
        CHECK(std::abs(point(k.vanishing_y).y) == doctest::Approx(1).epsilon(mtest::loose<T>()));
        const auto raw = frustum::raw_planes(*clipped);
        REQUIRE(raw.far.has_value());
        CHECK(std::abs(incidence(raw.near, k.vanishing_x)) <= loose<T>());
        CHECK(std::abs(incidence(*raw.far, k.vanishing_x)) <= loose<T>());
        // The same tilt about x gives the mirror image: O1 = (0, 8/3, 0).
        const auto clipped_y = frustum::clip_oblique(*base, Plane<T>(0, T(0.6), T(-0.8), T(-1.6)));
        REQUIRE(clipped_y.ok());
        const auto ky = frustum::key_points(*clipped_y);
        CHECK(point(ky.vanishing_y) == close_abs(Vec4<T>(0, T(8.0 / 3), 0, 1), 4 * loose<T>()));
        CHECK(ky.vanishing_x.w == 0);
    });
}

TEST_CASE_TEMPLATE("centre D lies on the three division planes (eq. 4)", T, float, double) {
    for_each_random_camera<T>(21, 500, [&](Random&, const CameraSpec&, const MatrixPair<T>& pair) {
        const auto d = frustum::division_planes(pair);
        const Vec4<T> centre = frustum::key_points(pair).center;
        CHECK(std::abs(incidence(d.x, centre)) <= loose<T>());
        CHECK(std::abs(incidence(d.y, centre)) <= loose<T>());
        CHECK(std::abs(incidence(d.z, centre)) <= loose<T>());
        // Dz is positive towards the far plane: Dz . C = s (z - z_mid) for a
        // corner whose clip point has w = 1, so far corners (even directions
        // at infinity) are positive and near ones negative.
        const auto k = frustum::key_points(pair);
        for (int j = 0; j < 4; ++j) {
            CHECK(d.z.evaluate(k.corners[j]) < 0);
            CHECK(d.z.evaluate(k.corners[j + 4]) > 0);
        }
    });
}

TEST_CASE_TEMPLATE("key points of random cameras: clip = M * C, eye -> w = 0, vanishing points", T, float, double) {
    // Each key point is a column combination of M^-1; M times it is the
    // clip-space point of eq. 6/8 up to rounding: within loose() of it
    // relative to its size (no rescaling: lambda = 1 for corners and D).
    for_each_random_camera<T>(22, 2000, [&](Random&, const CameraSpec& c, const MatrixPair<T>& pair) {
        const auto k = frustum::key_points(pair);
        const Mat4<T>& m = pair.matrix();
        for (int j = 0; j < 8; ++j) {
            CAPTURE(j);
            const Vec4<T> clip = frustum::clip_corner<T>(j, c.depth);
            CHECK(Vec4<T>(m * k.corners[j]) == close(clip, loose<T>()));
        }
        const T zm = frustum::clip_z_mid<T>(c.depth);
        CHECK(Vec4<T>(m * k.center) == close(Vec4<T>(0, 0, zm, 1), loose<T>()));
        // The eye is (0, 0, +-1, 0) in clip space: w = 0, on the line l of
        // eq. 5; its sign puts it behind the near plane.
        const Vec4<T> eye = m * k.eye;
        CHECK(std::abs(std::abs(double(eye.z)) - 1) <= loose<T>());
        CHECK(std::abs(double(eye.w)) <= loose<T>());
        CHECK(std::abs(double(eye.x)) + std::abs(double(eye.y)) <= loose<T>());
        CHECK(frustum::raw_planes(pair).near.evaluate(k.eye) < 0);
        // Vanishing points: (1, 0, 0, 0) and (0, 1, 0, 0) (eq. 6).
        CHECK(Vec4<T>(m * k.vanishing_x) == close(Vec4<T>(1, 0, 0, 0), loose<T>()));
        CHECK(Vec4<T>(m * k.vanishing_y) == close(Vec4<T>(0, 1, 0, 0), loose<T>()));
        // A finite eye for perspective kinds (w > 0), at infinity for ortho.
        if (c.kind == Kind::Orthographic) {
            CHECK(k.eye.w == 0);
        } else {
            CHECK(k.eye.w > 0);
            CHECK(point(k.eye) == close_abs(Vec4<T>(Vec3<T>(c.eye), 1), loose<T>() * 40));
        }
    });
}

// ---- the eye and its distances (eye_point, near_distance, far_distance,
// near_plane_frame), and Plane::at / through / facing, which they rely on.

TEST_CASE_TEMPLATE("eye_point, near_distance, far_distance of the landmark, by hand", T, float, double) {
    const double tol = loose<T>() * 20;
    for_each_depth_range([&](DepthRange depth) {
        const auto camera = landmark_at_e<T>(T(10), depth);
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
    });
}

TEST_CASE_TEMPLATE("far_distance refuses an infinite far plane; every query refuses an orthographic box", T, float,
                   double) {
    const auto infinite = landmark_at_e<T>(infinite_far, DepthRange::ZeroToOne);
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
