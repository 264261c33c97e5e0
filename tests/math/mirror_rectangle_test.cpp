// mirror_rectangle (paper §5.3, errata 4, 5, 13): a frustum from the
// reflected eye O' through a rectangular mirror, MirrorFit::Paper (axis
// through the mirror's centre) and MirrorFit::Exact (Kooima: near plane =
// mirror plane).
#include "support.hpp"

using namespace mtest;
using frustum::DepthRange;
using frustum::MirrorFit;
using frustum::Rectangle;

namespace {

// The 2 x 2 mirror in the plane z = 0: P1 = (-1, -1, 0), a1 = (0, 2, 0)
// (the camera's y axis follows a1), a2 = (2, 0, 0). Its normal
// unit(a1 x a2) = (0, 0, -1); N_w = -N.P1 = 0.
template <class T>
Rectangle<T> square_mirror() {
    return {{-1, -1, 0}, {0, 2, 0}, {2, 0, 0}};
}

template <class T>
std::array<Vec3<T>, 4> corners_of(const Rectangle<T>& r) {
    return {r.corner, r.corner + r.a1, r.corner + r.a1 + r.a2, r.corner + r.a2};
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("mirror_rectangle, eye on the mirror's axis: literal matrix, Paper == Exact", T, float, double) {
    // Eye E = (0, 0, 2): O' = (0, 0, -2) looks along +z at the mirror. Both
    // fits give the basis i = (-1, 0, 0), j = (0, 1, 0), k = (0, 0, -1)
    // (Paper: k = unit(O' - C), i = unit(a1 x k); Exact: k = the mirror's
    // normal pointing towards O', j = a1/|a1|, i = j x k), so eye space is
    //   x_e = -x, y_e = y, z_e = -(z + 2),
    // the window is [-1, 1]^2 at near 2, far 20:
    //   off_axis(-1, 1, -1, 1, 2, 20): sx = sy = 2, A = -20/18, B = -40/18.
    // M = P V rows: (-2, 0, 0, 0), (0, 2, 0, 0),
    //   (0, 0, -A, -2A + B) = (0, 0, 10/9, 0), (0, 0, 1, 2)   [ZeroToOne].
    const auto exact =
        frustum::mirror_rectangle(square_mirror<T>(), Vec3<T>(0, 0, 2), T(20), MirrorFit::Exact, DepthRange::ZeroToOne);
    const auto paper =
        frustum::mirror_rectangle(square_mirror<T>(), Vec3<T>(0, 0, 2), T(20), MirrorFit::Paper, DepthRange::ZeroToOne);
    REQUIRE_MESSAGE(exact.ok(), exact.error());
    REQUIRE_MESSAGE(paper.ok(), paper.error());
    const Mat4<T> expected = from_rows<T>({-2, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, T(10.0 / 9), 0}, {0, 0, 1, 2});
    CHECK(exact->matrix() == close(expected, tight<T>()));
    CHECK(paper->matrix() == close(expected, tight<T>()));
    CHECK(inverse_residual(*exact) <= 64 * eps<T>());
    // An ordinary (unreflected) camera at O': no winding flip, valid.
    CHECK_FALSE(exact->flips_winding());
    CHECK(frustum::validate(*exact).valid());
    const auto k = frustum::key_points(*exact);
    CHECK(frustum::to_point(k.eye, T(1e-6)) == close_abs(Vec4<T>(0, 0, -2, 1), loose<T>()));
}

TEST_CASE_TEMPLATE("mirror_rectangle Exact: the corners ARE the near rectangle; near plane == mirror plane", T, float,
                   double) {
    Random rng(101);
    for (int i = 0; i < 1000; ++i) {
        // A random rectangle (not necessarily square; a1 and a2 orthogonal)
        // and an eye 0.5..10 in front of it, anywhere sideways.
        const glm::dvec3 u = rng.unit_vector();
        glm::dvec3 v;
        do {
            v = glm::cross(u, rng.unit_vector());
        } while (glm::length(v) < 0.2);
        v = glm::normalize(v);
        const Rectangle<T> rect{Vec3<T>(rng.in_box(10)), Vec3<T>(u * rng.uniform(0.2, 5)),
                                Vec3<T>(v * rng.uniform(0.2, 5))};
        const glm::dvec3 n = glm::normalize(glm::cross(glm::dvec3(rect.a1), glm::dvec3(rect.a2)));
        const double side_sign = rng.coin() ? 1 : -1; // in front of either face
        const glm::dvec3 centre = glm::dvec3(rect.corner) + glm::dvec3(rect.a1 + rect.a2) / 2.0;
        glm::dvec3 sideways = rng.in_box(8);
        sideways -= n * glm::dot(n, sideways);
        const Vec3<T> eye(centre + n * side_sign * rng.uniform(0.5, 10) + sideways);
        const DepthRange depth = rng.depth();
        const double eye_distance = glm::dot(n, glm::dvec3(eye) - glm::dvec3(rect.corner));
        if (std::abs(eye_distance) < 0.3) continue;
        const auto m = frustum::mirror_rectangle(rect, eye, T(200), MirrorFit::Exact, depth);
        INFO("eye ", vec_text(eye), " corner ", vec_text(rect.corner), " a1 ", vec_text(rect.a1), " a2 ",
             vec_text(rect.a2));
        REQUIRE_MESSAGE(m.ok(), m.error());
        CHECK(inverse_residual(*m) <= 256 * eps<T>());
        // Each corner lands on a clip-space near corner (x, y = +-1,
        // z = z_near), and the four are the four different ones.
        int seen = 0;
        for (const Vec3<T>& corner : corners_of(rect)) {
            const glm::dvec4 c = glm::dmat4(m->matrix()) * glm::dvec4(glm::dvec3(corner), 1);
            const glm::dvec3 ndc = glm::dvec3(c) / c.w;
            CHECK(c.w > 0);
            CHECK(std::abs(std::abs(ndc.x) - 1) <= loose<T>() * 10);
            CHECK(std::abs(std::abs(ndc.y) - 1) <= loose<T>() * 10);
            CHECK(std::abs(ndc.z - frustum::clip_z_near<double>(depth)) <= loose<T>() * 10);
            seen |= 1 << ((ndc.x > 0) + 2 * (ndc.y > 0));
        }
        CHECK(seen == 15);
        // Near plane = mirror plane, inside towards the real eye.
        const Plane<T> near = frustum::planes(*m).near;
        const glm::dvec3 toward_eye = n * (eye_distance > 0 ? 1.0 : -1.0);
        const Plane<T> mirror_plane(Vec4<T>(glm::dvec4(toward_eye, -glm::dot(toward_eye, glm::dvec3(rect.corner)))));
        CHECK(near == close_abs(mirror_plane, loose<T>() * 40));
    }
}

TEST_CASE_TEMPLATE("mirror_rectangle Paper: the corners project onto the near face's edges", T, float, double) {
    // With the axis through the centre the near plane is perpendicular to
    // it through the nearest corner; the window is the bounding box of the
    // corners projected onto it, so every corner projects into [-1, 1]^2,
    // the extremes reach +-1, and the nearest corner is on the near plane.
    Random rng(102);
    int loose_window = 0;
    std::string first_loose;
    for (int i = 0; i < 1000; ++i) {
        const Rectangle<T> rect = square_mirror<T>();
        // z >= 1 keeps every corner in front of O' along the Paper axis:
        // (O' - C).(O' - P) >= |O'|^2 - |x| - |y| > 0 (see the next test).
        const double eye_z = rng.uniform(1, 8); // one draw per statement, z first (as always)
        const double eye_y = rng.uniform(-6, 6);
        const double eye_x = rng.uniform(-6, 6);
        const Vec3<T> eye(eye_x, eye_y, eye_z);
        const DepthRange depth = rng.depth();
        const auto m = frustum::mirror_rectangle(rect, eye, T(100), MirrorFit::Paper, depth);
        INFO("eye ", vec_text(eye));
        REQUIRE_MESSAGE(m.ok(), m.error());
        double min_x = 2, max_x = -2, min_y = 2, max_y = -2, nearest = 2;
        const double zn = frustum::clip_z_near<double>(depth), span = frustum::clip_z_span<double>(depth);
        for (const Vec3<T>& corner : corners_of(rect)) {
            const glm::dvec4 c = glm::dmat4(m->matrix()) * glm::dvec4(glm::dvec3(corner), 1);
            REQUIRE(c.w > 0);
            min_x = std::min(min_x, c.x / c.w), max_x = std::max(max_x, c.x / c.w);
            min_y = std::min(min_y, c.y / c.w), max_y = std::max(max_y, c.y / c.w);
            const double depth_fraction = (c.z / c.w - zn) / span; // 0 at near, 1 at far
            CHECK(depth_fraction >= -loose<T>() * 10);
            nearest = std::min(nearest, depth_fraction);
        }
        CHECK(min_x >= -1 - loose<T>() * 10);
        CHECK(max_x <= 1 + loose<T>() * 10);
        CHECK(min_y >= -1 - loose<T>() * 10);
        CHECK(max_y <= 1 + loose<T>() * 10);
        // The window is the bounding box: the extremes must reach the edges
        // (else the frustum also sees past the mirror's edge). Counted, so a
        // failure prints once with an example.
        const double slack = std::max({min_x + 1, 1 - max_x, min_y + 1, 1 - max_y});
        if (slack > loose<T>() * 10 && loose_window++ == 0) {
            first_loose = "eye " + vec_text(eye) + ": corners span x [" + num(min_x) + ", " + num(max_x) + "], y [" +
                          num(min_y) + ", " + num(max_y) + "]";
        }
        CHECK(std::abs(nearest) <= loose<T>() * 10);
        // The basis is orthonormal (erratum 13): the view part is rigid, so
        // the inverse is a componentwise inverse.
        CHECK(inverse_residual(*m) <= 256 * eps<T>());
    }
    // KNOWN LIBRARY PROBLEM when this fails: the bounding box starts from
    // the UNPROJECTED x[0], y[0] of corner P1 (mirror.cpp), so when P1 is
    // deeper than the near plane and extreme, the window is too wide.
    CHECK_MESSAGE(loose_window == 0, loose_window, " of 1000 Paper windows do not touch the corners, first: ",
                  first_loose);
}

TEST_CASE_TEMPLATE("mirror_rectangle Paper, oblique eye (3, 0, 2): the window by hand", T, float, double) {
    // O' = (3, 0, -2), k = (3, 0, -2)/sqrt13, i = (-2, 0, -3)/sqrt13,
    // j = (0, 1, 0) (see the leak test below). For corner P, v = P - O':
    //   P1 = (-1, -1, 0): v = (-4, -1, 2): x = v.i = 2/sqrt13, y = -1,
    //                     depth -v.k = 16/sqrt13
    //   (-1, 1, 0): x = 2/sqrt13, y = 1, depth 16/sqrt13
    //   (1, +-1, 0): v = (-2, +-1, 2): x = -2/sqrt13, y = +-1, depth 10/sqrt13
    // near = 10/sqrt13; projected onto it (times near/depth = 10/16 for
    // the far pair): x in {1.25/sqrt13, -2/sqrt13}, y in {+-0.625, +-1}.
    // The window is their bounding box [-2/sqrt13, 1.25/sqrt13] x [-1, 1]:
    // P1 projects onto the RIGHT edge (NDC x = +1) at y = -0.625 (NDC
    // -0.625), and (1, -1, 0) onto the bottom-left corner (-1, -1).
    const auto m = frustum::mirror_rectangle(square_mirror<T>(), Vec3<T>(3, 0, 2), T(20), MirrorFit::Paper,
                                             DepthRange::MinusOneToOne);
    REQUIRE_MESSAGE(m.ok(), m.error());
    const Vec4<T> p1 = m->matrix() * Vec4<T>(-1, -1, 0, 1);
    CHECK(p1.x / p1.w == doctest::Approx(1).epsilon(1e-5));
    CHECK(p1.y / p1.w == doctest::Approx(-0.625).epsilon(1e-5));
    const Vec4<T> p4 = m->matrix() * Vec4<T>(1, -1, 0, 1);
    CHECK(p4.x / p4.w == doctest::Approx(-1).epsilon(1e-5));
    CHECK(p4.y / p4.w == doctest::Approx(-1).epsilon(1e-5));
    CHECK(p4.z / p4.w == doctest::Approx(-1).epsilon(1e-5)); // on the near plane
    // Window width 3.25/sqrt13 at near 10/sqrt13: 2n/(r-l) = 20/3.25.
    const Vec4<T> row0 = frustum::row(m->matrix(), 0);
    const Vec4<T> row3 = frustum::row(m->matrix(), 3);
    // |row 0 xyz| / |row 3 xyz| = 2n/(r-l) for an unsheared camera frame.
    CHECK(glm::length(Vec3<T>(row0)) / glm::length(Vec3<T>(row3)) ==
          doctest::Approx(std::sqrt(std::pow(20 / 3.25, 2) + std::pow((1.25 - 2) / 3.25, 2))).epsilon(1e-5));
}

TEST_CASE_TEMPLATE("mirror_rectangle Paper cannot fit an eye close to the mirror and off-centre; Exact can", T, float,
                   double) {
    // Eye (-0.66, 0.45, 0.5): O' = (-0.66, 0.45, -0.5), axis k = unit(O').
    // The corner (-1, 1, 0) has depth -(P - O').k = -(0.2244 + 0.2475 -
    // 0.25)/|O'| = -0.23 < 0: behind O' along the Paper axis, so no frustum
    // with that axis contains the mirror. The Exact fit has no axis to
    // choose: the near plane is the mirror.
    const Vec3<T> eye(T(-0.66), T(0.45), T(0.5));
    const auto paper = frustum::mirror_rectangle(square_mirror<T>(), eye, T(20), MirrorFit::Paper, DepthRange::ZeroToOne);
    REQUIRE_FALSE(paper.ok());
    CHECK(paper.error().rfind("frustum::mirror_rectangle(): every corner must be in front of the reflected eye, got "
                              "nearest_depth=-0.2",
                              0) == 0);
    const auto exact = frustum::mirror_rectangle(square_mirror<T>(), eye, T(20), MirrorFit::Exact, DepthRange::ZeroToOne);
    REQUIRE_MESSAGE(exact.ok(), exact.error());
    CHECK(frustum::validate(*exact).valid());
}

TEST_CASE_TEMPLATE("mirror_rectangle: geometry behind the mirror leaks into the Paper frustum, not the Exact one", T,
                   float, double) {
    // Erratum 5, worked by hand. Eye E = (3, 0, 2) (oblique), mirror as
    // above: N.(E - P1) = -2, so O' = E - 2 (-2) N = (3, 0, -2). Paper axis:
    // k = unit(O' - C) = (3, 0, -2)/sqrt13, i = unit(a1 x k) =
    // (-2, 0, -3)/sqrt13, j = (0, 1, 0). Depths along -k: the corners at
    // x = +1 are nearest, 10/sqrt13 = 2.77 (the near plane, perpendicular
    // to k, NOT the mirror plane z = 0); the corners at x = -1 are at 4.44.
    // Take p = O' + 0.9 ((-0.8, 0, 0) - O') = (-0.42, 0, -0.2): on the ray
    // from O' through an interior point of the mirror, but 0.2 BEHIND the
    // mirror (z < 0, the real eye is at z > 0). Its depth is
    // 0.9 * 15.4/sqrt13 = 3.84 > 2.77, and it projects to x = 0.29 in a
    // window [-0.55, 0.35]: inside the Paper frustum. The Exact frustum's
    // near plane is z = 0, so p is outside it.
    const Vec3<T> eye(3, 0, 2);
    for_each_depth_range([&](DepthRange depth) {
        const auto paper = frustum::mirror_rectangle(square_mirror<T>(), eye, T(20), MirrorFit::Paper, depth);
        const auto exact = frustum::mirror_rectangle(square_mirror<T>(), eye, T(20), MirrorFit::Exact, depth);
        REQUIRE((paper.ok() && exact.ok()));
        const Vec4<T> p(T(-0.42), 0, T(-0.2), 1);
        CHECK(clip_inside(Vec4<T>(paper->matrix() * p), depth));       // the leak
        CHECK_FALSE(clip_inside(Vec4<T>(exact->matrix() * p), depth)); // no leak
        // The Paper near plane is tilted against the mirror by the angle
        // between k and the mirror normal: cos = 2/sqrt13.
        const Plane<T> near = frustum::planes(*paper).near;
        CHECK(std::abs(near.normal().z) == doctest::Approx(2 / std::sqrt(13.0)).epsilon(1e-5));
        CHECK(frustum::planes(*exact).near == close_abs(Plane<T>(0, 0, 1, 0), loose<T>()));
        // Both see a point in front of the mirror through its interior:
        // q = O' + 1.5 ((0, 0.3, 0) - O') = (-1.5, 0.45, 1).
        const Vec4<T> q(T(-1.5), T(0.45), 1, 1);
        CHECK(clip_inside(Vec4<T>(paper->matrix() * q), depth));
        CHECK(clip_inside(Vec4<T>(exact->matrix() * q), depth));
    });
}

TEST_CASE_TEMPLATE("mirror_rectangle errors: degenerate rectangle, eye in the mirror's plane, far <= near", T, float,
                   double) {
    const Vec3<T> eye(0, 0, 2);
    const Rectangle<T> parallel{{-1, -1, 0}, {0, 2, 0}, {0, 4, 0}};
    const auto a = frustum::mirror_rectangle(parallel, eye, T(20), MirrorFit::Exact, DepthRange::ZeroToOne);
    REQUIRE_FALSE(a.ok());
    CHECK(a.error() == "frustum::mirror_rectangle(): rectangle is degenerate (a1 and a2 parallel or zero), got "
                       "a1=(0, 2, 0) a2=(0, 4, 0)");
    const Rectangle<T> zero{{-1, -1, 0}, {0, 0, 0}, {2, 0, 0}};
    CHECK(frustum::mirror_rectangle(zero, eye, T(20), MirrorFit::Paper, DepthRange::ZeroToOne)
              .error()
              .find("rectangle is degenerate") != std::string::npos);
    for (const MirrorFit fit : {MirrorFit::Paper, MirrorFit::Exact}) {
        const auto in_plane = frustum::mirror_rectangle(square_mirror<T>(), Vec3<T>(5, 1, 0), T(20), fit,
                                                        DepthRange::ZeroToOne);
        REQUIRE_FALSE(in_plane.ok());
        CHECK(in_plane.error().find("eye must not lie in the mirror's plane") != std::string::npos);
        const auto shallow = frustum::mirror_rectangle(square_mirror<T>(), eye, T(1), fit, DepthRange::ZeroToOne);
        REQUIRE_FALSE(shallow.ok());
        CHECK(shallow.error().find("far must exceed the near distance") != std::string::npos);
        // NaN or infinity in each of the 13 scalars (corner, a1, a2, eye, far).
        for (const T bad : {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity()}) {
            for (int i = 0; i < 13; ++i) {
                Rectangle<T> r = square_mirror<T>();
                Vec3<T> e = eye;
                T far = 20;
                Vec3<T>* vectors[4] = {&r.corner, &r.a1, &r.a2, &e};
                if (i < 12) {
                    (*vectors[i / 3])[i % 3] = bad;
                } else {
                    far = bad;
                }
                CAPTURE(i);
                const auto result = frustum::mirror_rectangle(r, e, far, fit, DepthRange::ZeroToOne);
                REQUIRE_FALSE(result.ok());
                CHECK(result.error().rfind("frustum::mirror_rectangle(): corner, a1, a2, eye and far must be finite", 0) ==
                      0);
            }
        }
    }
}

} // TEST_SUITE
