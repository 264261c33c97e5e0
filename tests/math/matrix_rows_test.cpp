// from_rows (matrix_rows.hpp): a matrix literal in reading order, and the
// constructors that lay their matrices out with it, entry by entry.
#include "support.hpp"

using namespace mtest;

TEST_SUITE("math") {

TEST_CASE_TEMPLATE("from_rows: row i of the result is argument i, bit for bit", T, float, double) {
    const Vec4<T> r[4] = {{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}, {T(-0.0), T(0.1), T(1e-30), T(3e30)}};
    const Mat4<T> m = frustum::from_rows<T>(r[0], r[1], r[2], r[3]);
    for (int i = 0; i < 4; ++i) {
        CHECK(frustum::row(m, i) == r[i]);
    }
    CHECK(m[2][0] == T(3)); // GLM's [column][row]: row 0, column 2
    CHECK(std::signbit(m[0][3]));
}

TEST_CASE_TEMPLATE("off_axis and orthographic: every entry of both matrices as projection.hpp draws it", T, float,
                   double) {
    // The formulas of projection.hpp evaluated here in T, in the same
    // order, so the comparison is exact (==, not a tolerance).
    const T l = T(-0.7), r = T(1.3), b = T(-0.4), t = T(0.9), n = T(0.25), f = T(80);
    for_each_depth_range([&](DepthRange depth) {
        const T zn = frustum::clip_z_near<T>(depth), zf = frustum::clip_z_far<T>(depth);
        const auto p = frustum::off_axis<T>(l, r, b, t, n, f, depth);
        REQUIRE(p.ok());
        const T sx = T(2) * n / (r - l), sy = T(2) * n / (t - b);
        const T cx = (r + l) / (r - l), cy = (t + b) / (t - b);
        const T a = -(zf * f - zn * n) / (f - n), bb = -n * f * (zf - zn) / (f - n);
        CHECK(p->matrix() == from_rows<T>({sx, 0, cx, 0}, {0, sy, cy, 0}, {0, 0, a, bb}, {0, 0, -1, 0}));
        CHECK(p->inverse() == from_rows<T>({1 / sx, 0, 0, cx / sx}, {0, 1 / sy, 0, cy / sy}, {0, 0, 0, -1},
                                           {0, 0, 1 / bb, a / bb}));

        const auto o = frustum::orthographic<T>(l, r, b, t, n, f, depth);
        REQUIRE(o.ok());
        const T ox = T(2) / (r - l), oy = T(2) / (t - b);
        const T tx = -(r + l) / (r - l), ty = -(t + b) / (t - b);
        const T oa = -(zf - zn) / (f - n), ob = zn + oa * n;
        CHECK(o->matrix() == from_rows<T>({ox, 0, 0, tx}, {0, oy, 0, ty}, {0, 0, oa, ob}, {0, 0, 0, 1}));
        CHECK(o->inverse() == from_rows<T>({1 / ox, 0, 0, -tx / ox}, {0, 1 / oy, 0, -ty / oy},
                                           {0, 0, 1 / oa, -ob / oa}, {0, 0, 0, 1}));
    });
}

} // TEST_SUITE
