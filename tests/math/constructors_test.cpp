// Constructors (projection.hpp, matrix_pair.hpp): a literal expected matrix
// per factory and DepthRange, landmarks, fast path == general path, closed
// form == glm::inverse, and round trips.
#include "support.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

using namespace mtest;
using frustum::DepthRange;
using frustum::infinite_far;

namespace {

// The landmark camera of Magnum's FrustumTest: 90 degrees vertical, aspect
// 1, near 1, far 10. top = near tan(45 deg) = 1 = right, so
//   2n/(r-l) = 2/2 = 1,  2n/(t-b) = 1,  (r+l)/(r-l) = (t+b)/(t-b) = 0,
// and the depth row (0, 0, A, B) with (projection.hpp)
//   A = -(z_f f - z_n n)/(f - n),  B = -n f (z_f - z_n)/(f - n):
//   ZeroToOne      (0, 1):  A = -10/9,            B = -10/9
//   MinusOneToOne  (-1, 1): A = -(10 + 1)/9 = -11/9, B = -10*2/9 = -20/9
//   Reversed       (1, 0):  A = -(0 - 1)/9 = 1/9,   B = -10*(-1)/9 = 10/9
// and for an infinite far plane A = -z_f, B = -n (z_f - z_n):
//   ZeroToOne (-1, -1); MinusOneToOne (-1, -2); Reversed (0, 1).
// The inverse (z = -W, w = (Z - A W)/B ... solved by hand) has rows
//   (1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 0, -1), (0, 0, 1/B, A/B).
struct DepthRow {
    DepthRange depth;
    bool infinite;
    double a, b;
};
const DepthRow landmark_rows[] = {
    {DepthRange::ZeroToOne, false, -10.0 / 9, -10.0 / 9},
    {DepthRange::MinusOneToOne, false, -11.0 / 9, -20.0 / 9},
    {DepthRange::ReversedZeroToOne, false, 1.0 / 9, 10.0 / 9},
    {DepthRange::ZeroToOne, true, -1, -1},
    {DepthRange::MinusOneToOne, true, -1, -2},
    {DepthRange::ReversedZeroToOne, true, 0, 1},
};

template <class T>
std::optional<T> far_of(bool infinite, T far_m) {
    return infinite ? std::optional<T>() : std::optional<T>(far_m);
}

template <class T>
Mat4<T> landmark_matrix(const DepthRow& r) {
    return from_rows<T>({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, T(r.a), T(r.b)}, {0, 0, -1, 0});
}
template <class T>
Mat4<T> landmark_inverse(const DepthRow& r) {
    return from_rows<T>({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, -1}, {0, 0, T(1 / r.b), T(r.a / r.b)});
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("perspective: literal matrix and inverse of the 90-degree landmark per depth range", T, float,
                   double) {
    for (const DepthRow& r : landmark_rows) {
        INFO("r.depth=", frustum::to_string(r.depth));
        CAPTURE(r.infinite);
        const auto pair = frustum::perspective<T>(T(pi / 2), T(1), T(1), far_of<T>(r.infinite, T(10)), r.depth);
        REQUIRE_MESSAGE(pair.ok(), pair.error());
        // tan(pi/4) is 1 within an ulp in float; tight() is 64 ulp.
        CHECK(pair->matrix() == close(landmark_matrix<T>(r), tight<T>()));
        CHECK(pair->inverse() == close(landmark_inverse<T>(r), tight<T>()));
        CHECK(pair->depth() == r.depth);
        CHECK_FALSE(pair->flips_winding());
    }
}

TEST_CASE_TEMPLATE("perspective: landmarks per depth range (near -> z_near, far -> z_far, direction -> z_far)", T,
                   float, double) {
    for_each_depth_range([&](DepthRange depth) {
        const T zn = frustum::clip_z_near<T>(depth), zf = frustum::clip_z_far<T>(depth);
        const auto pair = frustum::perspective<T>(T(1.1), T(1.5), T(0.5), T(40), depth);
        REQUIRE(pair.ok());
        // Points on the near (z = -0.5) and far (z = -40) planes, off the axis.
        const Vec4<T> on_near = pair->matrix() * Vec4<T>(0.1, -0.2, -0.5, 1);
        const Vec4<T> on_far = pair->matrix() * Vec4<T>(7, 3, -40, 1);
        CHECK(on_near.z / on_near.w == doctest::Approx(zn).epsilon(1e-5));
        CHECK(on_far.z / on_far.w == doctest::Approx(zf).epsilon(1e-5));
        CHECK(on_near.w == doctest::Approx(0.5).epsilon(mtest::tight<T>())); // w = -z_eye
        // A point halfway in eye depth is strictly between (perspective
        // depth is not linear, but it is monotonic).
        const Vec4<T> mid = pair->matrix() * Vec4<T>(0, 0, -20, 1);
        CHECK((mid.z / mid.w - zn) * (zf - zn) > 0);
        CHECK((zf - mid.z / mid.w) * (zf - zn) > 0);

        // Infinite far: a DIRECTION (w = 0) lands exactly on z_far, and the
        // near plane still maps to z_near.
        const auto inf = frustum::perspective<T>(T(1.1), T(1.5), T(0.5), infinite_far, depth);
        REQUIRE(inf.ok());
        const Vec4<T> direction = inf->matrix() * Vec4<T>(0.3, -0.1, -1, 0);
        CHECK(direction.z / direction.w == doctest::Approx(zf).epsilon(1e-6));
        const Vec4<T> near_inf = inf->matrix() * Vec4<T>(0.1, -0.2, -0.5, 1);
        CHECK(near_inf.z / near_inf.w == doctest::Approx(zn).epsilon(1e-5));
        // ... and a far but finite point does not reach it.
        const Vec4<T> far_point = inf->matrix() * Vec4<T>(0, 0, -1000, 1);
        CHECK(std::abs(far_point.z / far_point.w - zf) > T(0));
    });
}

TEST_CASE_TEMPLATE("perspective equals glm's perspectiveRH_ZO / perspectiveRH_NO / infinitePerspectiveRH", T, float,
                   double) {
    const T fovy = T(0.9), aspect = T(16.0 / 9), n = T(0.25), f = T(300);
    const auto zo = frustum::perspective<T>(fovy, aspect, n, f, DepthRange::ZeroToOne);
    const auto no = frustum::perspective<T>(fovy, aspect, n, f, DepthRange::MinusOneToOne);
    const auto inf = frustum::perspective<T>(fovy, aspect, n, infinite_far, DepthRange::MinusOneToOne);
    REQUIRE((zo.ok() && no.ok() && inf.ok()));
    // "Up to sign": both put w = -z_eye > 0 in front, so the factor is +1.
    CHECK(zo->matrix() == close(glm::perspectiveRH_ZO(fovy, aspect, n, f), tight<T>()));
    CHECK(no->matrix() == close(glm::perspectiveRH_NO(fovy, aspect, n, f), tight<T>()));
    // glm::infinitePerspectiveRH is the [-1, 1] form (m22 = -1, m32 = -2n).
    CHECK(inf->matrix() == close(glm::infinitePerspectiveRH(fovy, aspect, n), tight<T>()));
    // Reversed-Z is ZeroToOne followed by z' = w - z.
    const auto rev = frustum::perspective<T>(fovy, aspect, n, f, DepthRange::ReversedZeroToOne);
    REQUIRE(rev.ok());
    const Mat4<T> flip = from_rows<T>({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 1}, {0, 0, 0, 1});
    CHECK(rev->matrix() == close(Mat4<T>(flip * glm::perspectiveRH_ZO(fovy, aspect, n, f)), tight<T>()));
}

TEST_CASE_TEMPLATE("off_axis: shifted window, literal matrix, equals glm::frustumRH_ZO and eq. 28", T, float, double) {
    // Shifted by (+1, 0) compared to the landmark: [l, r] = [0, 2], [b, t] =
    // [-1, 1], near 1, far 10. 2n/(r-l) = 1 and (r+l)/(r-l) = 1, so row 0 is
    // (1, 0, 1, 0): x_clip = x_eye + z_eye, and the window's centre
    // (1, 0, -1) on the near plane lands on x_clip = 0.
    const auto pair = frustum::off_axis<T>(0, 2, -1, 1, 1, T(10), DepthRange::ZeroToOne);
    REQUIRE(pair.ok());
    const Mat4<T> expected =
        from_rows<T>({1, 0, 1, 0}, {0, 1, 0, 0}, {0, 0, T(-10.0 / 9), T(-10.0 / 9)}, {0, 0, -1, 0});
    CHECK(pair->matrix() == close(expected, tight<T>()));
    CHECK(pair->matrix() == close(glm::frustumRH_ZO<T>(0, 2, -1, 1, 1, 10), tight<T>()));
    const Vec4<T> centre = pair->matrix() * Vec4<T>(1, 0, -1, 1);
    CHECK(centre.x == doctest::Approx(0).epsilon(mtest::tight<T>()));
    const Vec4<T> corner = pair->matrix() * Vec4<T>(2, 1, -1, 1);
    CHECK(corner.x / corner.w == doctest::Approx(1).epsilon(mtest::tight<T>()));
    CHECK(corner.y / corner.w == doctest::Approx(1).epsilon(mtest::tight<T>()));

    // Paper eq. 28 (row-vector form) is the [-1, 1] OpenGL matrix: written
    // out literally and transposed it equals off_axis(MinusOneToOne).
    const T l = T(-0.3), r = T(0.7), b = T(-0.2), t = T(0.4), n = T(0.5), f = T(50);
    const Mat4<T> eq28_paper = from_rows<T>({2 * n / (r - l), 0, 0, 0}, {0, 2 * n / (t - b), 0, 0},
                                           {(r + l) / (r - l), (t + b) / (t - b), -(f + n) / (f - n), -1},
                                           {0, 0, -2 * f * n / (f - n), 0});
    const auto gl = frustum::off_axis<T>(l, r, b, t, n, f, DepthRange::MinusOneToOne);
    REQUIRE(gl.ok());
    CHECK(gl->matrix() == close(Mat4<T>(glm::transpose(eq28_paper)), tight<T>()));
}

TEST_CASE_TEMPLATE("off_axis with symmetric bounds equals perspective (fast path == general path)", T, float,
                   double) {
    Random rng(11);
    for (int i = 0; i < 200; ++i) {
        const T fovy = T(rng.uniform(0.2, 2.8)), aspect = T(rng.uniform(0.3, 3)), n = T(rng.uniform(0.01, 5));
        const DepthRange depth = rng.depth();
        const std::optional<T> far = rng.coin() ? std::optional<T>() : std::optional<T>(n * T(rng.uniform(1.5, 1e4)));
        const auto p = frustum::perspective<T>(fovy, aspect, n, far, depth);
        REQUIRE(p.ok());
        const T top = n * std::tan(fovy / 2), right = top * aspect;
        const auto o = frustum::off_axis<T>(-right, right, -top, top, n, far, depth);
        REQUIRE(o.ok());
        // Same formula, same rounding: equal to the last ulp (perspective
        // funnels into off_axis).
        CHECK(o->matrix() == p->matrix());
        CHECK(o->inverse() == p->inverse());
    }
}

TEST_CASE_TEMPLATE("orthographic: literal matrix per depth range, equals glm::orthoRH_NO / orthoRH_ZO", T, float,
                   double) {
    // Box [-2, 2] x [-1, 1] x [-11, -1]: sx = 2/4 = 0.5, sy = 1, no shift;
    // clip z = a z_eye + b with a = -(z_f - z_n)/(f - n), b = z_n + a n:
    //   ZeroToOne: a = -0.1, b = -0.1   (z=-1 -> 0, z=-11 -> 1)
    //   MinusOne:  a = -0.2, b = -1.2   (z=-1 -> -1, z=-11 -> 1)
    //   Reversed:  a = 0.1,  b = 1.1    (z=-1 -> 1, z=-11 -> 0)
    const struct {
        DepthRange depth;
        double a, b;
    } rows[] = {{DepthRange::ZeroToOne, -0.1, -0.1},
                {DepthRange::MinusOneToOne, -0.2, -1.2},
                {DepthRange::ReversedZeroToOne, 0.1, 1.1}};
    for (const auto& r : rows) {
        INFO("r.depth=", frustum::to_string(r.depth));
        const auto pair = frustum::orthographic<T>(-2, 2, -1, 1, 1, 11, r.depth);
        REQUIRE(pair.ok());
        const Mat4<T> expected =
            from_rows<T>({T(0.5), 0, 0, 0}, {0, 1, 0, 0}, {0, 0, T(r.a), T(r.b)}, {0, 0, 0, 1});
        CHECK(pair->matrix() == close(expected, tight<T>()));
        // Inverse by hand: x = 2 X, y = Y, z = (Z - b)/a.
        const Mat4<T> inverse =
            from_rows<T>({2, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, T(1 / r.a), T(-r.b / r.a)}, {0, 0, 0, 1});
        CHECK(pair->inverse() == close(inverse, tight<T>()));
        const Vec4<T> near_point = pair->matrix() * Vec4<T>(1.5, -0.5, -1, 1);
        const Vec4<T> far_point = pair->matrix() * Vec4<T>(-2, 1, -11, 1);
        CHECK(near_point.z == doctest::Approx(frustum::clip_z_near<T>(r.depth)).epsilon(mtest::tight<T>()));
        CHECK(far_point.z == doctest::Approx(frustum::clip_z_far<T>(r.depth)).epsilon(mtest::tight<T>()));
        CHECK(far_point.x == doctest::Approx(-1).epsilon(mtest::tight<T>()));
        CHECK(far_point.y == doctest::Approx(1).epsilon(mtest::tight<T>()));
    }
    const T l = T(-3), r = T(5), b = T(-1), t = T(2), n = T(-4), f = T(7);
    CHECK(frustum::orthographic<T>(l, r, b, t, n, f, DepthRange::MinusOneToOne)->matrix() ==
          close(glm::orthoRH_NO(l, r, b, t, n, f), tight<T>()));
    CHECK(frustum::orthographic<T>(l, r, b, t, n, f, DepthRange::ZeroToOne)->matrix() ==
          close(glm::orthoRH_ZO(l, r, b, t, n, f), tight<T>()));
}

TEST_CASE_TEMPLATE("M * M^-1 = I and closed-form inverse == glm::inverse over 3000 random cameras", T, float,
                   double) {
    // Rotated views (look_at from random eyes), symmetric and off-axis
    // perspective (finite and infinite far), orthographic, all depth ranges.
    // Tolerances: the closed form and glm::inverse round differently; both
    // are within a few ulp of the exact inverse for these well-conditioned
    // cameras, so they agree column by column within loose() (2e-4 float,
    // 1e-12 double); and M * M^-1 - I is bounded componentwise by
    // 32 eps (|M| |M^-1|) (see inverse_residual; measured <= 6 eps), which
    // is what two matrices with a few ulp of error per entry give.
    for_each_random_camera<T>(12, 3000, [&](Random&, const CameraSpec&, const MatrixPair<T>& pair) {
        CHECK(column_relative_diff(pair.inverse(), glm::inverse(glm::dmat4(pair.matrix()))) <= loose<T>());
        CHECK(inverse_residual(pair) <= 32 * eps<T>());
    });
}

TEST_CASE_TEMPLATE("look_at: equals glm::lookAtRH, its inverse equals glm::inverse, landmark", T, float, double) {
    // Landmark: from (0, 0, 5) towards the origin with y up is a pure
    // translation by (0, 0, -5).
    const auto simple = frustum::look_at<T>({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
    REQUIRE(simple.ok());
    Mat4<T> translation(1);
    translation[3] = Vec4<T>(0, 0, -5, 1);
    CHECK(simple->matrix == close(translation, tight<T>()));
    // Looking along +x with y up: the camera's x axis is forward x up = +z,
    // so the view matrix maps world +z to eye +x and the target to -z.
    const auto side = frustum::look_at<T>({1, 2, 3}, {4, 2, 3}, {0, 1, 0});
    REQUIRE(side.ok());
    CHECK(Vec4<T>(side->matrix * Vec4<T>(1, 2, 4, 1)) == close_abs(Vec4<T>(1, 0, 0, 1), tight<T>()));
    CHECK(Vec4<T>(side->matrix * Vec4<T>(4, 2, 3, 1)) == close_abs(Vec4<T>(0, 0, -3, 1), 4 * tight<T>()));

    Random rng(13);
    for (int i = 0; i < 300; ++i) {
        // One draw per statement (operand order is unspecified): the length
        // before the direction, the order these cases were always drawn in.
        const Vec3<T> eye(rng.in_box(50));
        const double distance = rng.uniform(0.1, 20);
        const Vec3<T> target(Vec3<T>(eye) + Vec3<T>(rng.unit_vector() * distance));
        Vec3<T> up;
        do {
            const double up_length = rng.uniform(0.1, 10);
            up = Vec3<T>(rng.unit_vector() * up_length);
        } while (glm::length(glm::cross(glm::normalize(target - eye), glm::normalize(up))) < T(0.05));
        const auto view = frustum::look_at(eye, target, up);
        REQUIRE(view.ok());
        // Coordinates up to ~70: the translation column carries ~70 eps.
        const Mat4<T> reference = glm::lookAtRH(eye, target, up);
        CHECK(view->matrix == close(reference, tight<T>()));
        CHECK(view->inverse == close(Mat4<T>(glm::inverse(glm::dmat4(reference))), tight<T>()));
        CHECK(inverse_residual(view->matrix, view->inverse) <= 32 * eps<T>());
    }
}

TEST_CASE_TEMPLATE("compose: M = P V and M^-1 = V^-1 P^-1", T, float, double) {
    const auto p = frustum::perspective<T>(T(1), T(1.3), T(0.2), T(80), DepthRange::ReversedZeroToOne);
    const auto v = frustum::look_at<T>({3, -1, 2}, {-4, 0.5, -6}, {0.2, 1, 0});
    REQUIRE((p.ok() && v.ok()));
    const MatrixPair<T> m = frustum::compose(*p, *v);
    CHECK(m.matrix() == close(Mat4<T>(p->matrix() * v->matrix), tight<T>()));
    CHECK(m.inverse() == close(Mat4<T>(v->inverse * p->inverse()), tight<T>()));
    CHECK(column_relative_diff(m.inverse(), glm::inverse(glm::dmat4(m.matrix()))) <= loose<T>());
    CHECK(m.depth() == DepthRange::ReversedZeroToOne);
    // The eye of the view is where the composed frustum's eye is.
    const auto eye = frustum::eye_point(m);
    REQUIRE(eye.has_value());
    CHECK(*eye == close_abs(Vec3<T>(3, -1, 2), 1e3 * tight<T>()));
}

TEST_CASE_TEMPLATE("from_matrix: a glm matrix gives the constructor's pair, sign normalized", T, float, double) {
    const T fovy = T(1.2), aspect = T(0.75), n = T(0.3), f = T(30);
    const auto built = frustum::perspective<T>(fovy, aspect, n, f, DepthRange::MinusOneToOne);
    const auto imported = frustum::from_matrix<T>(glm::perspectiveRH_NO(fovy, aspect, n, f), DepthRange::MinusOneToOne);
    REQUIRE((built.ok() && imported.ok()));
    CHECK(imported->matrix() == close(built->matrix(), tight<T>()));
    CHECK(column_relative_diff(imported->inverse(), built->inverse()) <= loose<T>());
    CHECK(inverse_residual(*imported) <= 32 * eps<T>());

    // -M is the same projective map; the pair is scaled to w > 0 inside,
    // so importing -M gives +M back.
    const auto negated = frustum::from_matrix<T>(-glm::perspectiveRH_NO(fovy, aspect, n, f), DepthRange::MinusOneToOne);
    REQUIRE(negated.ok());
    CHECK(negated->matrix() == close(built->matrix(), tight<T>()));
    CHECK(negated->matrix()[2][3] == T(-1)); // w = -z_eye: positive in front

    // The identity is the clip box itself: an orthographic cube.
    const auto identity = frustum::from_matrix<T>(Mat4<T>(1), DepthRange::MinusOneToOne);
    REQUIRE(identity.ok());
    CHECK(identity->inverse() == Mat4<T>(1));
    CHECK(frustum::validate(*identity).valid());
}

TEST_CASE_TEMPLATE("with_depth_range: equals direct construction, round trips, same world frustum", T, float, double) {
    for (const DepthRange from : all_depth_ranges) {
        for (const DepthRange to : all_depth_ranges) {
            INFO("from=", frustum::to_string(from));
            INFO("to=", frustum::to_string(to));
            for (const bool infinite : {false, true}) {
                const auto a = frustum::perspective<T>(T(1), T(1.5), T(0.5), far_of<T>(infinite, T(20)), from);
                const auto b = frustum::perspective<T>(T(1), T(1.5), T(0.5), far_of<T>(infinite, T(20)), to);
                REQUIRE((a.ok() && b.ok()));
                const MatrixPair<T> converted = a->with_depth_range(to);
                CHECK(converted.depth() == to);
                CHECK(converted.matrix() == close(b->matrix(), tight<T>()));
                CHECK(converted.inverse() == close(b->inverse(), tight<T>()));
            }
            const auto oa = frustum::orthographic<T>(-3, 1, -2, 2, -1, 9, from);
            const auto ob = frustum::orthographic<T>(-3, 1, -2, 2, -1, 9, to);
            REQUIRE((oa.ok() && ob.ok()));
            CHECK(oa->with_depth_range(to).matrix() == close(ob->matrix(), tight<T>()));
            CHECK(oa->with_depth_range(to).inverse() == close(ob->inverse(), tight<T>()));
        }
    }
    // Random rotated cameras: there and back again, and the six world
    // planes do not move.
    for_each_random_camera<T>(14, 300, [&](Random& rng, const CameraSpec& c, const MatrixPair<T>& pair) {
        const DepthRange other = all_depth_ranges[(int(c.depth) + 1 + rng.index(2)) % 3];
        const MatrixPair<T> there = pair.with_depth_range(other);
        const MatrixPair<T> back = there.with_depth_range(c.depth);
        CHECK(back.matrix() == close(pair.matrix(), tight<T>()));
        CHECK(column_relative_diff(back.inverse(), pair.inverse()) <= tight<T>());
        // Row 2 becomes a m2 + b m3, which cancels for some rows: the
        // componentwise bound grows (measured up to ~90 ulp), so 256 ulp.
        CHECK(inverse_residual(there) <= 256 * eps<T>());
        const auto p0 = frustum::planes(pair), p1 = frustum::planes(there);
        CHECK(p1.near == close_abs(p0.near, loose<T>() * (1 + max_abs(p0.near))));
        CHECK(p1.far.has_value() == p0.far.has_value());
        if (p0.far && p1.far) {
            CHECK(*p1.far == close_abs(*p0.far, loose<T>() * (1 + max_abs(*p0.far))));
        }
        CHECK(p1.left == close_abs(p0.left, loose<T>() * (1 + max_abs(p0.left))));
    });
}

TEST_CASE("cast: double -> float equals the float constructor; flags carried") {
    const auto d = frustum::perspective<double>(1.0, 1.25, 0.1, 100.0, DepthRange::ReversedZeroToOne);
    const auto f = frustum::perspective<float>(1.0f, 1.25f, 0.1f, 100.0f, DepthRange::ReversedZeroToOne);
    REQUIRE((d.ok() && f.ok()));
    const MatrixPair<float> cast = d->cast<float>();
    CHECK(cast.depth() == DepthRange::ReversedZeroToOne);
    // Each entry rounded once from double vs computed in float: a few ulp.
    CHECK(cast.matrix() == close(f->matrix(), tight<float>()));
    CHECK(cast.inverse() == close(f->inverse(), tight<float>()));
    // float -> double is exact.
    const MatrixPair<double> widened = f->cast<double>();
    CHECK(widened.matrix() == glm::dmat4(f->matrix()));
    CHECK(widened.inverse() == glm::dmat4(f->inverse()));
    // flips_winding survives the cast.
    const auto reflected = frustum::reflect(*d, frustum::Plane<double>(0, 1, 0, 2));
    REQUIRE(reflected.ok());
    CHECK(reflected->cast<float>().flips_winding());
}

} // TEST_SUITE
