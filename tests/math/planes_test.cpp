// Planes from the matrix (paper §3.1, queries.hpp) over thousands of random
// well-conditioned cameras: which corners each plane contains, the inward
// convention (the centre D is inside all six), and that the planes classify
// points exactly as clip space does.
#include "support.hpp"

using namespace mtest;
using frustum::DepthRange;

namespace {

// Corners (0-based, eq. 8 order) on each plane. Clip x = -1 for C2, C3,
// C6, C7; x = +1 for C1, C4, C5, C8; y = -1 for C3, C4, C7, C8; y = +1
// for C1, C2, C5, C6; near C1..C4; far C5..C8.
const int corners_on[6][4] = {{1, 2, 5, 6}, {0, 3, 4, 7}, {2, 3, 6, 7}, {0, 1, 4, 5}, {0, 1, 2, 3}, {4, 5, 6, 7}};
const char* const plane_names[6] = {"left", "right", "bottom", "top", "near", "far"};

// Float: the cameras have far/near up to 200 and coordinates up to ~400,
// so a plane (rows of M) evaluated at a corner (columns of M^-1) is a sum
// of terms up to cond(M) ~ 1e3 times the result: ~1e-4 relative in float.
// The sampled points are kept this far inside/outside in clip units.
template <class T>
constexpr double classification_margin() {
    return sizeof(T) == sizeof(float) ? 1e-2 : 1e-6;
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("planes of the 90-degree landmark, by hand", T, float, double) {
    // M rows m0 = (1,0,0,0), m1 = (0,1,0,0), m3 = (0,0,-1,0):
    //   L = m3 + m0 = (1, 0, -1, 0)/sqrt2   (x >= z_eye... i.e. x >= -(-z))
    //   R = m3 - m0 = (-1, 0, -1, 0)/sqrt2, B = (0, 1, -1, 0)/sqrt2,
    //   T = (0, -1, -1, 0)/sqrt2, N = (0, 0, -1, -1): -z >= 1,
    //   F = (0, 0, 1, 10): -z <= 10, in EVERY depth range.
    const T h = T(1 / std::sqrt(2.0));
    for_each_depth_range([&](DepthRange depth) {
        const auto pair = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), depth);
        REQUIRE(pair.ok());
        const auto p = frustum::planes(*pair);
        CHECK(p.left == close_abs(Plane<T>(h, 0, -h, 0), tight<T>()));
        CHECK(p.right == close_abs(Plane<T>(-h, 0, -h, 0), tight<T>()));
        CHECK(p.bottom == close_abs(Plane<T>(0, h, -h, 0), tight<T>()));
        CHECK(p.top == close_abs(Plane<T>(0, -h, -h, 0), tight<T>()));
        CHECK(p.near == close_abs(Plane<T>(0, 0, -1, -1), tight<T>()));
        REQUIRE(p.far.has_value());
        CHECK(*p.far == close_abs(Plane<T>(0, 0, 1, 10), 16 * tight<T>()));
        // Infinite: no far plane (erratum 9), the other five unchanged.
        const auto inf = frustum::perspective<T>(T(pi / 2), 1, 1, frustum::infinite_far, depth);
        REQUIRE(inf.ok());
        const auto pi_ = frustum::planes(*inf);
        CHECK_FALSE(pi_.far.has_value());
        CHECK(pi_.near == close_abs(Plane<T>(0, 0, -1, -1), tight<T>()));
        CHECK(pi_.left == close_abs(Plane<T>(h, 0, -h, 0), tight<T>()));
    });
}

TEST_CASE_TEMPLATE("each plane contains its four corners; normalized; far absent iff infinite", T, float, double) {
    for_each_random_camera<T>(31, 2000, [&](Random&, const CameraSpec& c, const MatrixPair<T>& pair) {
        const auto p = frustum::planes(pair);
        const auto k = frustum::key_points(pair);
        CHECK(p.far.has_value() == !c.infinite);
        const auto all = p.as_array();
        for (int j = 0; j < 6; ++j) {
            CAPTURE(plane_names[j]);
            if (!all[std::size_t(j)]) continue;
            const Plane<T>& plane = *all[std::size_t(j)];
            CHECK(glm::length(plane.normal()) == doctest::Approx(1).epsilon(tight<T>()));
            for (const int corner : corners_on[j]) {
                CAPTURE(corner);
                CHECK(std::abs(incidence(plane, k.corners[std::size_t(corner)])) <= loose<T>());
            }
            // ... and the opposite corners are strictly inside it.
            for (int corner = 0; corner < 8; ++corner) {
                const int* on = corners_on[j];
                if (std::find(on, on + 4, corner) != on + 4) continue;
                const Vec4<T>& h = k.corners[std::size_t(corner)];
                if (h.w > 0) CHECK(plane.distance(Vec3<T>(h) / h.w) > 0);
            }
        }
    });
}

TEST_CASE_TEMPLATE("the centre D is at positive distance from all six planes (inward convention)", T, float, double) {
    for_each_random_camera<T>(32, 2000, [&](Random&, const CameraSpec&, const MatrixPair<T>& pair) {
        const Vec4<T> d = frustum::key_points(pair).center;
        REQUIRE(d.w > 0);
        const Vec3<T> centre = Vec3<T>(d) / d.w;
        const auto all = frustum::planes(pair).as_array();
        for (int j = 0; j < 6; ++j) {
            CAPTURE(plane_names[j]);
            if (all[std::size_t(j)]) CHECK(all[std::size_t(j)]->distance(centre) > 0);
        }
    });
}

TEST_CASE_TEMPLATE("points just inside / outside each plane are classified like clip space says", T, float, double) {
    // Random clip points are taken back through M^-1; each plane's sign at
    // the world point must be the sign of its clip inequality (x >= -w,
    // x <= w, ..., z between z_near and z_far). One coordinate is moved just
    // across one plane, the others stay inside.
    const double delta = classification_margin<T>();
    Random rng(33);
    int outside_checked = 0;
    for (int i = 0; i < 1500; ++i) {
        const CameraSpec c = random_camera(rng);
        const MatrixPair<T> pair = make<T>(c);
        INFO(c.text());
        const auto all = frustum::planes(pair).as_array();
        const double zn = frustum::clip_z_near<double>(c.depth), span = frustum::clip_z_span<double>(c.depth);
        for (int s = 0; s < 4; ++s) {
            const double x = rng.uniform(-1 + delta, 1 - delta), y = rng.uniform(-1 + delta, 1 - delta);
            const double t = rng.uniform(delta, 1 - delta);
            for (int moved = -1; moved < 6; ++moved) {
                for (const int direction : {-1, +1}) { // -1: just outside, +1: just inside
                    if (moved == -1 && direction == -1) continue;
                    glm::dvec4 clip(x, y, zn + t * span, 1);
                    const double to_edge = 1 + (direction < 0 ? delta : -delta);
                    switch (moved) {
                    case 0: clip.x = -to_edge; break;
                    case 1: clip.x = to_edge; break;
                    case 2: clip.y = -to_edge; break;
                    case 3: clip.y = to_edge; break;
                    case 4: clip.z = zn + (direction < 0 ? -delta : delta) * span; break;
                    case 5: clip.z = zn + (direction < 0 ? 1 + delta : 1 - delta) * span; break;
                    default: break;
                    }
                    // Beyond an infinite far plane is beyond infinity.
                    if (moved == 5 && !all[5]) continue;
                    // Beyond a finite far plane, clip z reaches the value
                    // where world w = 0 (the points behind the eye) soon:
                    // at z_f + 2n/(f - n) for MinusOneToOne. Halve the step
                    // until the point keeps at least half its far-plane w.
                    if (moved == 5 && direction < 0) {
                        const glm::dvec4 row3(pair.inverse()[0][3], pair.inverse()[1][3], pair.inverse()[2][3],
                                              pair.inverse()[3][3]);
                        const double w_far = glm::dot(row3, glm::dvec4(clip.x, clip.y, zn + span, 1));
                        double step = delta;
                        while (glm::dot(row3, glm::dvec4(clip.x, clip.y, zn + (1 + step) * span, 1)) < 0.5 * w_far &&
                               step > 1e-12)
                            step /= 2;
                        clip.z = zn + (1 + step) * span;
                    }
                    const Vec4<T> h = pair.inverse() * Vec4<T>(clip);
                    CAPTURE(moved);
                    CAPTURE(direction);
                    REQUIRE(h.w > 0);
                    for (int j = 0; j < 6; ++j) {
                        if (!all[std::size_t(j)]) continue;
                        const double value = side(*all[std::size_t(j)], h);
                        const bool expect_outside = (j == moved && direction < 0);
                        CHECK((expect_outside ? value < 0 : value > 0));
                    }
                    outside_checked += (moved >= 0 && direction < 0);
                }
            }
        }
    }
    CHECK(outside_checked > 30000);
}

TEST_CASE("planes() of an imported matrix whose left plane is the plane at infinity") {
    // Rows m0 = (0, 0, 1, 0), m1 = (0, 1, 0, 0), m2 = (1, 0, 0, 0),
    // m3 = (0, 0, -1, 1): det = -1, so from_matrix accepts it, but
    // L = m3 + m0 = (0, 0, 0, 1) has a zero normal. (validate() rejects the
    // frustum: near corners at infinity.) planes() promises normalized
    // planes; Plane::normalized() keeps a plane at infinity as
    // (0, 0, 0, sign d) instead of dividing by its zero normal length.
    const auto pair = frustum::from_matrix<double>(
        from_rows<double>({0, 0, 1, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, -1, 1}), DepthRange::ZeroToOne);
    REQUIRE(pair.ok());
    CHECK_FALSE(frustum::validate(*pair).valid());
    CHECK(frustum::raw_planes(*pair).left.is_degenerate(1e-12));
    const auto p = frustum::planes(*pair);
    CHECK_MESSAGE(p.left.abcd == glm::dvec4(0, 0, 0, 1), "left = ", vec_text(p.left.abcd));
}

TEST_CASE_TEMPLATE("raw planes are positive multiples of the normalized ones", T, float, double) {
    for_each_random_camera<T>(34, 300, [&](Random&, const CameraSpec&, const MatrixPair<T>& pair) {
        const auto raw = frustum::raw_planes(pair).as_array();
        const auto unit = frustum::planes(pair).as_array();
        for (std::size_t j = 0; j < 6; ++j) {
            REQUIRE(raw[j].has_value() == unit[j].has_value());
            if (!raw[j]) continue;
            const Factor f = factor_between(unit[j]->abcd, raw[j]->abcd);
            CHECK(f.lambda > 0);
            CHECK(f.residual <= tight<T>());
        }
    });
}

} // TEST_SUITE
