// clip_oblique (paper §5.2 second step, erratum 2 and 7): the clip plane
// becomes the near plane, the far plane passes through the far corner Q
// chosen in clip space, and the inverse is updated analytically.
#include "support.hpp"

using namespace mtest;
using frustum::DepthRange;
using frustum::infinite_far;

namespace {

// Tolerances for classifying sampled points: they are kept delta inside
// the old box and delta (relative, clip units) away from the clip plane;
// the new matrix must agree up to tol (float: cond ~1e3 times 1e-7).
template <class T>
constexpr double sample_margin() {
    return sizeof(T) == sizeof(float) ? 1e-2 : 1e-6;
}
template <class T>
constexpr double classify_tol() {
    return sizeof(T) == sizeof(float) ? 1e-4 : 1e-10;
}

double sgn(double v) {
    return v > 0 ? 1 : v < 0 ? -1 : 0;
}

// The paper's own choice (eq. 19-22) with the WORLD-space signs of the
// plane, Q = M^-1 (sgn c_x, sgn c_y, z_f, 1), k = (m3.Q)/(c.Q) = 1/(c.Q),
// new row 2 = (z_f - z_n) k c + z_n m3. Built here in double to compare.
glm::dmat4 paper_world_sign_clip(const glm::dmat4& m, const glm::dmat4& inv, DepthRange d, const glm::dvec4& c) {
    const double zn = frustum::clip_z_near<double>(d), zf = frustum::clip_z_far<double>(d);
    const glm::dvec4 q = inv * glm::dvec4(sgn(c.x), sgn(c.y), zf, 1);
    const double k = 1 / glm::dot(c, q);
    glm::dmat4 out = m;
    frustum::set_row(out, 2, (zf - zn) * k * c + zn * frustum::row(m, 3));
    return out;
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("clip_oblique with a plane parallel to the near plane moves the near plane", T, float, double) {
    // Landmark (90 deg, near 1, far 10) clipped by c = (0, 0, -1, -2):
    // keep -z >= 2. In clip space c'_x = c'_y = 0, so q = (1, 1, z_f, 1)
    // and Q = M^-1 q is the far corner (10, 10, -10) with clip w = 1, i.e.
    // homogeneous (1, 1, -1, 0.1): k = 1/(c.Q) = 1/(1 - 0.2) = 1.25.
    // New row 2 (ZeroToOne) = k c = (0, 0, -1.25, -2.5), which is
    // A = -f/(f-n), B = -nf/(f-n) for near 2, far 10: exactly
    // off_axis(-2, 2, -2, 2, near 2, far 10), in every depth range.
    for_each_depth_range([&](DepthRange depth) {
        const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), depth);
        const auto moved = frustum::off_axis<T>(-2, 2, -2, 2, 2, T(10), depth);
        REQUIRE((base.ok() && moved.ok()));
        const auto clipped = frustum::clip_oblique(*base, Plane<T>(0, 0, -1, -2));
        REQUIRE_MESSAGE(clipped.ok(), clipped.error());
        CHECK(clipped->matrix() == close(moved->matrix(), tight<T>()));
        CHECK(clipped->inverse() == close(moved->inverse(), tight<T>()));
        CHECK(clipped->depth() == depth);
        CHECK_FALSE(clipped->flips_winding());
    });
}

TEST_CASE_TEMPLATE("clip_oblique, tilted landmark: near = the plane, far through Q, sides unchanged", T, float, double) {
    // c = (0.6, 0, -0.8, -1.6): z = 0.75 x - 2, eye at c = -1.6 < 0.
    // c' = (c . m0', c . m1', ...) has c'_x = 0.6 > 0 and c'_y = 0, so
    // q = (1, 1, z_f, 1): Q is the far corner (10, 10, -10); the far
    // corners on the x = +10 side are the farthest from the plane
    // (c = 0.6*10 + 8 - 1.6 = 12.4 there, 0.4 at x = -10).
    for_each_depth_range([&](DepthRange depth) {
        const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), depth);
        REQUIRE(base.ok());
        const Plane<T> c(T(0.6), 0, T(-0.8), T(-1.6));
        const auto clipped = frustum::clip_oblique(*base, c);
        REQUIRE_MESSAGE(clipped.ok(), clipped.error());
        const auto p = frustum::planes(*clipped);
        const auto p0 = frustum::planes(*base);
        CHECK(p.near == close_abs(c, loose<T>()));
        REQUIRE(p.far.has_value());
        CHECK(std::abs(p.far->distance({10, 10, -10})) <= loose<T>() * 10);
        CHECK(std::abs(p.far->distance({10, -10, -10})) <= loose<T>() * 10);
        // The two other far corners are strictly inside the new far plane.
        CHECK(p.far->distance({-10, 10, -10}) > 1);
        CHECK(p.left == close_abs(p0.left, tight<T>()));
        CHECK(p.top == close_abs(p0.top, tight<T>()));
        // Rows 0, 1 and 3 are untouched (clip x, y, w of every point).
        for (const int r : {0, 1, 3}) {
            CHECK(frustum::row(clipped->matrix(), r) == frustum::row(base->matrix(), r));
        }
        CHECK(inverse_residual(*clipped) <= 64 * eps<T>());
    });
}

TEST_CASE_TEMPLATE("clip_oblique keeps w > 0 inside when the plane crosses the view axis behind the eye", T, float,
                   double) {
    // c = (1, 0, 0.2, -1)/|.|: keep x >= 1 + 0.2 t at depth t = -z. The
    // eye is behind it (c(0) < 0); the right edges x = t cross it at
    // t = 1.25 in front, the left edges x = -t only behind the eye
    // (t = -1/1.2), and so does the view axis (t = -5). The kept region is
    // not empty: (5, 0, -8) has x = 5 >= 1 + 1.6, |x| <= t = 8, t <= 10.
    // Its clip coordinates must therefore be inside the clip box with
    // w = 8 > 0 (rows 0, 1, 3 are those of the input). A pair scaled by
    // -1 would put w < 0 and the GPU would clip everything away.
    for_each_depth_range([&](DepthRange depth) {
        const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), depth);
        REQUIRE(base.ok());
        const auto clipped = frustum::clip_oblique(*base, Plane<T>(1, 0, T(0.2), -1));
        REQUIRE_MESSAGE(clipped.ok(), clipped.error());
        const Vec4<T> clip = clipped->matrix() * Vec4<T>(5, 0, -8, 1);
        CHECK(clip.w == doctest::Approx(8).epsilon(mtest::tight<T>()));
        CHECK(clip_inside(clip, depth));
        CHECK(frustum::row(clipped->matrix(), 3) == frustum::row(base->matrix(), 3));
    });
}

TEST_CASE_TEMPLATE("clip_oblique semantics on random rotated / off-axis / orthographic cameras", T, float, double) {
    // For a plane through the frustum with the eye behind it:
    //  - points of the input frustum clearly on the plane's positive side
    //    are inside the clipped frustum (the far plane through Q keeps all
    //    of them: F . q = 1 - c'.q / c'.q* >= 0 for every far corner q);
    //  - points clearly on its negative side are outside;
    //  - the new near plane is the clip plane, the far plane passes
    //    through Q, the side planes and rows 0, 1, 3 are unchanged.
    // The overall sign (w > 0 inside) is counted separately so that one
    // known problem does not hide the rest (see the previous test case).
    const double delta = sample_margin<T>(), tol = classify_tol<T>();
    int negated = 0, kept = 0, removed = 0;
    std::string first_negated;
    for_each_random_camera<T>(61, 1500, [&](Random& rng, const CameraSpec& c, const MatrixPair<T>& pair) {
        const Plane<T> plane = random_plane_through(rng, pair, true);
        INFO("plane ", vec_text(plane.abcd));
        const auto clipped = frustum::clip_oblique(pair, plane);
        REQUIRE_MESSAGE(clipped.ok(), clipped.error());
        // Sign: row 3 is the input's row 3, or (wrongly) its negation.
        const double sign = glm::dot(glm::dvec4(frustum::row(clipped->matrix(), 3)),
                                     glm::dvec4(frustum::row(pair.matrix(), 3))) > 0 ? 1 : -1;
        if (sign < 0 && negated++ == 0) first_negated = c.text() + " plane " + vec_text(plane.abcd);
        const glm::dmat4 m = glm::dmat4(clipped->matrix()) * sign;
        for (const int r : {0, 1, 3}) {
            CHECK(glm::dvec4(frustum::row(m, r)) == glm::dvec4(frustum::row(pair.matrix(), r)));
        }
        // Near plane == clip plane (normalized, same orientation): compare
        // through the sign-corrected raw planes.
        const Plane<double> near_raw(frustum::clip_z_span<double>(c.depth) > 0
                                         ? frustum::row(m, 2) - frustum::clip_z_near<double>(c.depth) * frustum::row(m, 3)
                                         : frustum::clip_z_near<double>(c.depth) * frustum::row(m, 3) - frustum::row(m, 2));
        const Plane<double> plane_d(glm::dvec4(plane.abcd));
        CHECK(near_raw.normalized() == close_abs(plane_d, loose<T>() * (1 + std::abs(plane_d.offset()))));
        // Far plane through Q, the far corner picked in clip space.
        const glm::dvec4 cc = clip_space_plane(pair, plane);
        const double zf = frustum::clip_z_far<double>(c.depth);
        const glm::dvec4 q(cc.x >= 0 ? 1 : -1, cc.y >= 0 ? 1 : -1, zf, 1);
        const glm::dvec4 big_q = glm::dmat4(pair.inverse()) * q;
        const Plane<double> far_raw(frustum::clip_z_span<double>(c.depth) > 0
                                        ? zf * frustum::row(m, 3) - frustum::row(m, 2)
                                        : frustum::row(m, 2) - zf * frustum::row(m, 3));
        CHECK(std::abs(incidence(far_raw, big_q)) <= loose<T>());
        // Sampled points.
        const double cc_norm = glm::length(cc);
        for (int s = 0; s < 30; ++s) {
            const glm::dvec4 u = random_clip_point(rng, c.depth, delta);
            const double side_value = glm::dot(cc, u) / cc_norm;
            const glm::dvec4 h = glm::dmat4(pair.inverse()) * u;
            const glm::dvec4 clip = m * glm::dvec4(Vec4<T>(h)); // the point as T, through the new matrix
            if (side_value > delta) {
                ++kept;
                CHECK(clip_inside(clip, c.depth, -tol));
            } else if (side_value < -delta) {
                ++removed;
                CHECK_FALSE(clip_inside(clip, c.depth, -tol));
            }
        }
    });
    CHECK(kept > 5000);
    CHECK(removed > 5000);
    // KNOWN LIBRARY PROBLEM when this fails: PairFactory's sign test looks
    // at the near face's centre, which for such planes maps behind the eye,
    // and negates a correct pair (~15% of these random planes).
    CHECK_MESSAGE(negated == 0, negated, " of 1500 clipped pairs came back negated (w < 0 inside), first: ",
                  first_negated);
}

TEST_CASE("clip_oblique analytic inverse (eq. 24-27) vs exact inverse, float against a double reference") {
    // Erratum 7: measure before claiming. The reference is glm::inverse in
    // double of the FLOAT matrix clip_oblique produced (so it is the exact
    // inverse of what a float renderer uses). Columns are compared on their
    // own scale. Tolerance 2e-3: these random planes tilt the near plane
    // up to ~80 degrees, the clipped matrices have cond up to ~3e4, and
    // float carries 6e-8 relative: 3e4 * 6e-8 ~ 2e-3 (measured: median
    // 1.4e-6, p99 8e-5, worst 5e-4). The float re-inversion
    // (glm::inverse<float>) is measured next to it (median 5e-7, worst 9e-5).
    std::vector<double> analytic, reinverted;
    int over = 0;
    for_each_random_camera<float>(62, 2000, [&](Random& rng, const CameraSpec&, const MatrixPair<float>& pair) {
        const auto clipped = frustum::clip_oblique(pair, random_plane_through(rng, pair, true));
        REQUIRE_MESSAGE(clipped.ok(), clipped.error());
        const glm::dmat4 reference = glm::inverse(glm::dmat4(clipped->matrix()));
        analytic.push_back(column_relative_diff(clipped->inverse(), reference));
        reinverted.push_back(column_relative_diff(glm::inverse(clipped->matrix()), reference));
        over += analytic.back() > 2e-3;
        CHECK(inverse_residual(*clipped) <= 1024 * eps<float>());
    });
    CHECK(over == 0);
    std::sort(analytic.begin(), analytic.end());
    std::sort(reinverted.begin(), reinverted.end());
    // The analytic update is NOT more accurate than re-inverting in float
    // (measured: median ~2.6x, worst ~5.6x the error of glm::inverse<float>);
    // it is cheaper. Pinned loosely so a regression shows.
    CHECK(analytic[analytic.size() / 2] <= 10 * reinverted[reinverted.size() / 2] + 1e-7);
    CHECK(analytic[analytic.size() / 2] <= 1e-5);

    // Double: same computation, tolerance scaled by eps ratio (1e-3 * 1e-9).
    for_each_random_camera<double>(63, 1000, [&](Random& rng_d, const CameraSpec&, const MatrixPair<double>& pair) {
        const auto clipped = frustum::clip_oblique(pair, random_plane_through(rng_d, pair, true));
        REQUIRE(clipped.ok());
        CHECK(column_relative_diff(clipped->inverse(), glm::inverse(clipped->matrix())) <= 1e-11);
    });
}

TEST_CASE("clip_oblique: the paper's world-space sign choice for Q loses visible geometry (erratum 2)") {
    // Camera at the origin looking along +z (look_at to (0, 0, 1), y up):
    // its x axis is forward x up = (0,0,1) x (0,1,0) = (-1, 0, 0), so world
    // +x is clip -x. 90 degrees, near 1, far 10, ZeroToOne. Clip plane
    // c = (0.6, 0, 0.8, -1.6): keep 0.6 x + 0.8 z >= 1.6; eye: -1.6 < 0.
    // Far corners are at z = 10, x = +-10: c = +-6 + 6.4, so the farthest
    // is x = +10 (c = 12.4), which is clip x = -1.
    //  - Paper: sgn(c_x) = +1 picks clip x = +1, the world x = -10 corner,
    //    c.Q = 0.4 (for Q with w_clip = 1: 0.04), k = 25.
    //  - Clip space (ours): c'_x < 0 picks clip x = -1, k = 1/1.24.
    // The point p = (5, 0, 8) is visible: inside the frustum (|x| <= z) and
    // on the kept side (3 + 6.4 - 1.6 = 7.8 > 0). Its clip w is 8; the far
    // plane is F = w - k (c.p) in clip units (ZeroToOne: m3 - m2):
    //   paper: 8 - 25 * 7.8 < 0 (clipped away); ours: 8 - 7.8/1.24 > 0.
    const auto projection = frustum::perspective<double>(pi / 2, 1, 1, 10.0, DepthRange::ZeroToOne);
    const auto view = frustum::look_at<double>({0, 0, 0}, {0, 0, 1}, {0, 1, 0});
    REQUIRE((projection.ok() && view.ok()));
    const MatrixPair<double> camera = frustum::compose(*projection, *view);
    const Plane<double> c(0.6, 0, 0.8, -1.6);
    const glm::dvec4 p(5, 0, 8, 1);
    CHECK(clip_inside(camera.matrix() * p, DepthRange::ZeroToOne));
    CHECK(c.evaluate(p) == doctest::Approx(7.8).epsilon(mtest::tight<double>()));

    const auto ours = frustum::clip_oblique(camera, c);
    REQUIRE(ours.ok());
    const glm::dvec4 in_ours = ours->matrix() * p;
    CHECK(clip_inside(in_ours, DepthRange::ZeroToOne));
    CHECK(in_ours.w - in_ours.z == doctest::Approx(8 - 7.8 / 1.24).epsilon(mtest::tight<double>()));

    const glm::dmat4 paper = paper_world_sign_clip(camera.matrix(), camera.inverse(), DepthRange::ZeroToOne, c.abcd);
    const glm::dvec4 in_paper = paper * p;
    CHECK_FALSE(clip_inside(in_paper, DepthRange::ZeroToOne));
    CHECK(in_paper.w - in_paper.z == doctest::Approx(8 - 25 * 7.8).epsilon(mtest::tight<double>()));
    // The whole far corner column at world x = +10 is lost as well.
    CHECK_FALSE(clip_inside(paper * glm::dvec4(9.9, 0, 9.95, 1), DepthRange::ZeroToOne));
    CHECK(clip_inside(ours->matrix() * glm::dvec4(9.9, 0, 9.95, 1), DepthRange::ZeroToOne));
}

TEST_CASE("clip_oblique: over random rotated views the paper's choice often loses geometry, ours never") {
    Random rng(64);
    int paper_loses = 0, ours_loses = 0, cases = 0;
    for (int i = 0; i < 1000; ++i) {
        CameraOptions options;
        options.orthographic = false;
        options.infinite = false;
        const CameraSpec c = random_camera(rng, options);
        const MatrixPair<double> pair = make<double>(c);
        const Plane<double> plane = random_plane_through(rng, pair, true);
        const auto ours = frustum::clip_oblique(pair, plane);
        REQUIRE(ours.ok());
        const glm::dmat4 paper = paper_world_sign_clip(pair.matrix(), pair.inverse(), c.depth, plane.abcd);
        const glm::dvec4 cc = clip_space_plane(pair, plane);
        bool lost_paper = false, lost_ours = false;
        for (int s = 0; s < 50; ++s) {
            const glm::dvec4 u = random_clip_point(rng, c.depth, 1e-3);
            if (glm::dot(cc, u) / glm::length(cc) <= 1e-3) continue; // only visible, kept points
            const glm::dvec4 h = pair.inverse() * u;
            const glm::dvec4 a = paper * h, b = ours->matrix() * h;
            // Sign-insensitive: a point is lost when it is outside for
            // both signs of the matrix (so the sign problem does not count).
            lost_paper = lost_paper || (!clip_inside(a, c.depth, -1e-9) && !clip_inside(-a, c.depth, -1e-9));
            lost_ours = lost_ours || (!clip_inside(b, c.depth, -1e-9) && !clip_inside(-b, c.depth, -1e-9));
        }
        ++cases;
        paper_loses += lost_paper;
        ours_loses += lost_ours;
    }
    CHECK(ours_loses == 0);
    // docs/errata.md (erratum 2) measured 66% on its sample; assert a clear share.
    CHECK(paper_loses > cases / 5);
}

TEST_CASE_TEMPLATE("clip_oblique with an infinite far plane", T, float, double) {
    for_each_depth_range([&](DepthRange depth) {
        const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, infinite_far, depth);
        REQUIRE(base.ok());
        // Tilted plane: Q is a direction (far corner at infinity) and the
        // new far plane is finite: it contains the line {c = 0, w = 0} and
        // the direction Q.
        const Plane<T> tilted(T(0.6), 0, T(-0.8), T(-1.6));
        const auto clipped = frustum::clip_oblique(*base, tilted);
        REQUIRE_MESSAGE(clipped.ok(), clipped.error());
        const auto p = frustum::planes(*clipped);
        REQUIRE(p.far.has_value());
        CHECK(p.near == close_abs(tilted, loose<T>()));
        // Q = direction of the clip corner (1, 1, z_f): (1, 1, -1).
        CHECK(std::abs(incidence(*p.far, Vec4<T>(1, 1, -1, 0))) <= loose<T>());
        CHECK(clip_inside(Vec4<T>(clipped->matrix() * Vec4<T>(50, 0, -60, 1)), depth));
        CHECK(inverse_residual(*clipped) <= 64 * eps<T>());
        // A plane parallel to the near plane: {c = 0, w = 0} is at infinity
        // too, so the "far plane through Q" is the plane at infinity: the
        // result is the infinite frustum with near plane z = -20.
        const auto parallel = frustum::clip_oblique(*base, Plane<T>(0, 0, -1, -20));
        const auto moved = frustum::perspective<T>(T(pi / 2), 1, 20, infinite_far, depth);
        REQUIRE((parallel.ok() && moved.ok()));
        CHECK_FALSE(frustum::planes(*parallel).far.has_value());
        CHECK(parallel->matrix() == close(moved->matrix(), tight<T>()));
        CHECK(clip_inside(Vec4<T>(parallel->matrix() * Vec4<T>(0, 0, -1e6, 1)), depth));
    });
}

TEST_CASE_TEMPLATE("clip_oblique errors: eye on the wrong side, plane through the eye, nothing visible", T, float,
                   double) {
    const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), DepthRange::ZeroToOne);
    const auto inf = frustum::perspective<T>(T(pi / 2), 1, 1, infinite_far, DepthRange::ZeroToOne);
    REQUIRE((base.ok() && inf.ok()));
    // c = (0, 0, -1, 1): c(eye) = 1 > 0. On the infinite landmark
    // (B = -1) the eye column is m2' = (0, 0, 0, -1), so c'_z = -1 and
    // eye_side = (z_f - z_n) c'_z = -1: exact numbers in the message.
    const auto wrong = frustum::clip_oblique(*inf, Plane<T>(0, 0, -1, 1));
    REQUIRE_FALSE(wrong.ok());
    CHECK(wrong.error() == "frustum::clip_oblique(): the eye must be on the clip plane's negative side, got "
                           "plane=(0, 0, -1, 1) eye_side=-1");
    CHECK_FALSE(frustum::clip_oblique(*base, Plane<T>(0, 0, -1, 1)).ok());
    // Through the eye: x = 0.
    const auto through = frustum::clip_oblique(*base, Plane<T>(1, 0, 0, 0));
    REQUIRE_FALSE(through.ok());
    CHECK(through.error().find("clip plane must not pass through the eye") != std::string::npos);
    // Keep -z >= 20 of a frustum that ends at -z = 10: nothing left.
    const auto nothing = frustum::clip_oblique(*base, Plane<T>(0, 0, -1, -20));
    REQUIRE_FALSE(nothing.ok());
    CHECK(nothing.error().rfind("frustum::clip_oblique(): clip plane leaves no part of the frustum visible", 0) == 0);
    // Same on the infinite frustum: it reaches -z = 20, so that works.
    CHECK(frustum::clip_oblique(*inf, Plane<T>(0, 0, -1, -20)).ok());
    // Unnormalized planes are accepted (scaled), a zero normal is not.
    const auto scaled = frustum::clip_oblique(*base, Plane<T>(0, 0, -4, -8));
    const auto unit = frustum::clip_oblique(*base, Plane<T>(0, 0, -1, -2));
    REQUIRE((scaled.ok() && unit.ok()));
    CHECK(scaled->matrix() == close(unit->matrix(), tight<T>()));
    const auto zero = frustum::clip_oblique(*base, Plane<T>(0, 0, 0, -1));
    REQUIRE_FALSE(zero.ok());
    CHECK(zero.error() == "frustum::clip_oblique(): plane normal must be non-zero and finite, got (0, 0, 0, -1)");
}

} // TEST_SUITE
