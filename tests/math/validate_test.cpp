// validate() (paper §5.5): the near face is a convex quadrilateral that
// separates the eye from the body. Ordinary cameras pass; hand-built bad
// matrices fail with the right reason(); the literal §5.5 test rejects many
// obliquely clipped frustums (docs/errata.md erratum 14), pinned as a known miss.
#include "support.hpp"

#include <glm/ext/matrix_clip_space.hpp>

using namespace mtest;
using frustum::DepthRange;

namespace {

// A matrix given by its inverse (world = inv * clip), imported.
template <class T>
frustum::Result<MatrixPair<T>> from_inverse(const Mat4<T>& inverse, DepthRange depth) {
    return frustum::from_matrix<T>(Mat4<T>(glm::inverse(glm::dmat4(inverse))), depth);
}

// A plane given in the pair's clip space, taken to world space (c = M^T c').
template <class T>
Plane<T> world_plane(const MatrixPair<T>& pair, const glm::dvec4& clip_plane) {
    const glm::dvec4 c = glm::transpose(glm::dmat4(pair.matrix())) * clip_plane;
    return Plane<T>(Vec4<T>(c / glm::length(glm::dvec3(c))));
}

// validate(pair), CHECKed to be invalid for `reason`; returned for the
// flags a case checks besides.
template <class T>
frustum::Validation invalid_because(const MatrixPair<T>& pair, const std::string& reason) {
    const frustum::Validation v = frustum::validate(pair);
    CHECK_FALSE(v.valid());
    CHECK(v.reason() == reason);
    return v;
}

// The same for a constructed pair, REQUIREd to be built.
template <class T>
frustum::Validation invalid_because(const frustum::Result<MatrixPair<T>>& pair, const std::string& reason) {
    REQUIRE_MESSAGE(pair.ok(), pair.error());
    return invalid_because(*pair, reason);
}

} // namespace

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("validate: ordinary cameras are valid", T, float, double) {
    for_each_depth_range([&](DepthRange depth) {
        const auto a = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), depth);
        const auto b = frustum::perspective<T>(T(0.1), T(3), T(0.01), frustum::infinite_far, depth);
        const auto c = frustum::off_axis<T>(T(0.5), T(3), T(-2), T(-0.25), T(1), T(10), depth);
        const auto d = frustum::orthographic<T>(-2, 2, -1, 1, -5, 11, depth);
        for (const auto* pair : {&a, &b, &c, &d}) {
            REQUIRE(pair->ok());
            const frustum::Validation v = frustum::validate(**pair);
            CHECK(v.valid());
            CHECK(v.reason() == "");
        }
    });
    for_each_random_camera<T>(51, 1000, [&](Random&, const CameraSpec& c, const MatrixPair<T>& pair) {
        const frustum::Validation v = frustum::validate(pair);
        CHECK_MESSAGE(v.valid(), c.text(), ": ", v.reason());
    });
}

TEST_CASE_TEMPLATE("validate: a bow-tie near face is not convex", T, float, double) {
    // world = inv * clip with world w = x_clip + 0.5 (last row of inv):
    // the near corners (z = 0) C1 (1, 1) and C4 (1, -1) get w = 1.5, C2
    // (-1, 1) and C3 (-1, -1) get w = -0.5, so after division
    //   C1 = (2/3, 2/3, 0), C2 = (2, -2, 0), C3 = (2, 2, 0), C4 = (2/3, -2/3, 0):
    // the sides C1C2 and C3C4 cross, a self-intersecting quad. The centre
    // of the near face has w = 0.5 > 0, so no sign flip on import.
    const Mat4<T> inv = from_rows<T>({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {1, 0, 0, T(0.5)});
    const auto pair = from_inverse(inv, DepthRange::ZeroToOne);
    REQUIRE_MESSAGE(pair.ok(), pair.error());
    const auto k = frustum::key_points(*pair);
    CHECK(frustum::to_point(k.corners[1], T(1e-6)) == close_abs(Vec4<T>(2, -2, 0, 1), loose<T>()));
    const frustum::Validation v = invalid_because(*pair, "near face is not a convex quadrilateral");
    CHECK(v.near_quad_finite);
    CHECK_FALSE(v.near_quad_convex);
}

TEST_CASE_TEMPLATE("validate: a near corner at infinity", T, float, double) {
    // world w = x_clip + 1: C2 = (-1, 1, 0, 1) and C3 get w = 0.
    const Mat4<T> inv = from_rows<T>({1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {1, 0, 0, 1});
    const auto pair = from_inverse(inv, DepthRange::ZeroToOne);
    const frustum::Validation v = invalid_because(pair, "near corners are not all finite points");
    CHECK_FALSE(v.near_quad_finite);
}

TEST_CASE_TEMPLATE("validate: the eye in front of the near plane (near and far swapped)", T, float, double) {
    // glm's [0, 1] matrix with near = 10, far = 1 maps z = -10 to 0 and
    // z = -1 to 1: the "near" plane is z = -10, its inside faces the eye.
    const auto pair = frustum::from_matrix<T>(glm::perspectiveRH_ZO<T>(T(pi / 2), 1, 10, 1), DepthRange::ZeroToOne);
    const frustum::Validation v = invalid_because(pair, "eye is not on the near plane's negative side");
    CHECK(v.near_quad_convex);
    CHECK_FALSE(v.eye_behind_near);
}

TEST_CASE_TEMPLATE("validate: far corners behind the eye", T, float, double) {
    // glm's [0, 1] matrix with near = 1, far = -5: z = -1 -> 0, but z = +5
    // (behind the eye) -> 1. Clip w = -z_eye is -5 there, so the far corners
    // come back from M^-1 with w < 0.
    const auto pair = frustum::from_matrix<T>(glm::perspectiveRH_ZO<T>(T(pi / 2), 1, 1, -5), DepthRange::ZeroToOne);
    const frustum::Validation v =
        invalid_because(pair, "far corners are not all in front of the eye beyond the near plane");
    CHECK(v.near_quad_convex);
    CHECK(v.eye_behind_near);
    CHECK_FALSE(v.far_corners_beyond);
}

TEST_CASE_TEMPLATE("validate: KNOWN MISS, literal §5.5 rejects many obliquely clipped frustums (erratum 14)", T, float,
                   double) {
    // Like Filament's BoxCulling "expected false classification": this
    // documents a limitation, it is not a goal. Random clip planes through
    // valid frustums with the eye behind them all pass clip_oblique's own
    // checks, yet §5.5 taken literally calls a large share "invalid", for
    // two different reasons:
    //  (a) the plane cuts all four side edges in front of the eye (a
    //      bounded near face), but the tilted far plane (through the eye's
    //      w = 0 plane and the far corner Q) meets some side edges only
    //      behind the eye: far corners with w <= 0 (erratum 14 proper);
    //  (b) the plane misses a side edge in front of the eye (e.g. water
    //      seen up to the horizon): the near "quad" is not a bounded convex
    //      quadrilateral at all.
    int proper = 0, proper_invalid = 0, improper = 0, improper_invalid = 0;
    for_each_random_camera<T>(52, 1000, [&](Random& rng, const CameraSpec& c, const MatrixPair<T>& pair) {
        REQUIRE(frustum::validate(pair).valid());
        const double s = frustum::clip_z_span<double>(c.depth) > 0 ? 1 : -1;
        // One draw per statement (argument order is unspecified), z first:
        // the order these cases were always drawn in.
        const double p0_z = clip_z_at<double>(c.depth, rng.uniform(0.05, 0.9));
        const double p0_y = rng.uniform(-0.8, 0.8);
        const double p0_x = rng.uniform(-0.8, 0.8);
        const glm::dvec3 p0(p0_x, p0_y, p0_z);
        const double n_z = s * rng.uniform(0.2, 1);
        const double n_y = rng.uniform(-1, 1);
        const double n_x = rng.uniform(-1, 1);
        const glm::dvec3 n(n_x, n_y, n_z);
        const Plane<T> plane = world_plane(pair, glm::dvec4(n, -glm::dot(n, p0)));
        const auto clipped = frustum::clip_oblique(pair, plane);
        REQUIRE_MESSAGE(clipped.ok(), clipped.error());
        const frustum::Validation v = frustum::validate(*clipped);
        // Borderline planes (an edge cut nearly at infinity) are skipped:
        // there float and double may disagree on the side.
        const double margin = edge_cut_margin(pair, plane);
        if (std::abs(margin) < 1e-3) return;
        if (margin > 0) {
            ++proper;
            if (!v.valid()) {
                ++proper_invalid;
                CHECK(v.near_quad_convex);
                CHECK(v.reason() == "far corners are not all in front of the eye beyond the near plane");
            }
        } else {
            ++improper;
            improper_invalid += !v.valid();
            CHECK(v.reason() == "near face is not a convex quadrilateral");
        }
    });
    // Measured with this seed (float and double alike): 437 proper, 136 of
    // them invalid; 562 improper, all invalid; 1 borderline skipped. So
    // 301 of 1000 pass (docs/errata.md: 433 of 2000 on its own sample).
    CHECK(proper > 200);
    CHECK(proper_invalid > 0);
    CHECK(proper_invalid < proper); // most proper clips stay valid
    CHECK(improper > 200);
    CHECK(improper_invalid == improper);
}

} // TEST_SUITE
