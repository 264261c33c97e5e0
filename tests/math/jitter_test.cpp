// jitter (jitter.hpp): J M and M^-1 J^-1, composable with the other ops.
#include "support.hpp"

using namespace mtest;

namespace {

// perspective(1 rad, 16:9, 0.1, 50) looking from (1, 2, 5) at the origin,
// built (make: REQUIREd) and CHECKed valid.
template <class T>
MatrixPair<T> camera(DepthRange depth) {
    CameraSpec c;
    c.depth = depth;
    c.fovy = 1, c.aspect = 16.0 / 9, c.near_m = 0.1, c.far_m = 50;
    c.eye = {1, 2, 5}, c.target = {0, 0, 0}, c.up = {0, 1, 0};
    const MatrixPair<T> pair = make<T>(c);
    CHECK(frustum::validate(pair).valid());
    return pair;
}

} // namespace

TEST_SUITE("math") {

TEST_CASE("halton_jitter_px: Halton(2,3) minus 1/2") {
    CHECK(frustum::halton_jitter_px<double>(0) == frustum::Vec2<double>(-0.5, -0.5));
    CHECK(frustum::halton_jitter_px<double>(1) == frustum::Vec2<double>(0.0, 1.0 / 3 - 0.5));
    CHECK(frustum::halton_jitter_px<double>(2).x == 0.25 - 0.5);
    CHECK(frustum::halton_jitter_px<double>(2).y == doctest::Approx(2.0 / 3 - 0.5).epsilon(mtest::tight<double>()));
    CHECK(frustum::halton_jitter_px<double>(3).x == 0.75 - 0.5);
    CHECK(frustum::halton_jitter_px<double>(3).y == doctest::Approx(1.0 / 9 - 0.5).epsilon(mtest::tight<double>()));
}

TEST_CASE_TEMPLATE("jitter: rows 0 and 1 pick up 2 dx / W and 2 dy / H times row 3; inverse column 3 follows", T, float,
                   double) {
    for (const DepthRange depth : all_depth_ranges) {
        const MatrixPair<T> pair = camera<T>(depth);
        const auto j = frustum::jitter(pair, T(0.25), T(-0.5), T(1280), T(720));
        REQUIRE_MESSAGE(j.ok(), j.error());
        const T tx = T(0.5 / 1280), ty = T(-1.0 / 720);
        const Mat4<T>& m = pair.matrix();
        CHECK(frustum::row(j->matrix(), 0) == close(frustum::row(m, 0) + tx * frustum::row(m, 3), tight<T>()));
        CHECK(frustum::row(j->matrix(), 1) == close(frustum::row(m, 1) + ty * frustum::row(m, 3), tight<T>()));
        CHECK(frustum::row(j->matrix(), 2) == frustum::row(m, 2));
        CHECK(frustum::row(j->matrix(), 3) == frustum::row(m, 3));
        CHECK(j->inverse()[0] == pair.inverse()[0]);
        CHECK(j->inverse()[1] == pair.inverse()[1]);
        CHECK(j->inverse()[2] == pair.inverse()[2]);
        CHECK(inverse_residual(*j) <= 64 * eps<T>());
        CHECK(j->depth() == depth);
    }
}

TEST_CASE_TEMPLATE("jitter: over 8 Halton(2,3) samples, pixel centres unproject onto the rays of the jittered pixels",
                   T, float, double) {
    // Rendering with the jittered pair puts the world point that the
    // unjittered camera sees at sub-pixel position (u, v) at (u + dx, v + dy).
    // So the jittered inverse must take pixel centre (i + 1/2, j + 1/2), at
    // any depth, to a point the unjittered camera sees at
    // (i + 1/2 - dx, j + 1/2 - dy): on the ray of the jittered pixel.
    const int width = 32, height = 18;
    for (const DepthRange depth : all_depth_ranges) {
        const MatrixPair<T> pair = camera<T>(depth);
        for (int s = 1; s <= 8; ++s) {
            const double dx = frustum::halton_jitter_px<double>(s).x, dy = frustum::halton_jitter_px<double>(s).y;
            const auto jittered = frustum::jitter(pair, T(dx), T(dy), T(width), T(height));
            REQUIRE(jittered.ok());
            double worst_px = 0;
            for (int j = 0; j < height; ++j) {
                for (int i = 0; i < width; ++i) {
                    for (const double t : {0.0, 0.5, 0.99}) {
                        const Vec4<T> clip(T(2 * (i + 0.5) / width - 1), T(2 * (j + 0.5) / height - 1),
                                           clip_z_at<T>(depth, t), T(1));
                        const Vec4<T> world = jittered->inverse() * clip;
                        const Vec4<T> seen = pair.matrix() * world;
                        const double u = (double(seen.x / seen.w) + 1) * width / 2;
                        const double v = (double(seen.y / seen.w) + 1) * height / 2;
                        worst_px = std::max({worst_px, std::abs(u - (i + 0.5 - dx)), std::abs(v - (j + 0.5 - dy))});
                        // Same depth too: the jitter moves the image, not the depth.
                        CHECK(std::abs(double(seen.z / seen.w) - double(clip.z)) <= loose<T>() * 50);
                    }
                }
            }
            INFO("sample ", s, " dx=", dx, " dy=", dy);
            CHECK(worst_px <= (sizeof(T) == 4 ? 2e-3 : 1e-9));
        }
    }
}

TEST_CASE_TEMPLATE("jitter composes: commutes with reflect and (in pixels) with crop; with mirror only row 2 differs",
                   T, float, double) {
    const MatrixPair<T> pair = camera<T>(DepthRange::ZeroToOne);
    const Plane<T> floor(0, 1, 0, T(0.5));
    // reflect acts from the right (M R), jitter from the left (J M).
    const auto a = frustum::jitter(*frustum::reflect(pair, floor), T(0.3), T(0.7), T(64), T(36));
    const auto b = frustum::reflect(*frustum::jitter(pair, T(0.3), T(0.7), T(64), T(36)), floor);
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    CHECK(a->matrix() == close(b->matrix(), tight<T>()));
    CHECK(a->inverse() == close(b->inverse(), tight<T>()));
    // jitter(crop(p, r), dx, dy, r.width, r.height) == crop(jitter(p, dx, dy, W, H), r).
    const frustum::CropRect<T> r{16, 9, 32, 18, 64, 36};
    const auto c = frustum::jitter(*frustum::crop(pair, r), T(0.3), T(0.7), r.width, r.height);
    const auto d = frustum::crop(*frustum::jitter(pair, T(0.3), T(0.7), r.full_width, r.full_height), r);
    REQUIRE(c.ok());
    REQUIRE(d.ok());
    CHECK(c->matrix() == close(d->matrix(), tight<T>()));
    CHECK(c->inverse() == close(d->inverse(), tight<T>()));
    // mirror: the same image shift and near plane; only the far plane's tilt (k) differs.
    const auto e = frustum::jitter(*frustum::mirror(pair, floor), T(0.3), T(0.7), T(64), T(36));
    const auto f = frustum::mirror(*frustum::jitter(pair, T(0.3), T(0.7), T(64), T(36)), floor);
    REQUIRE(e.ok());
    REQUIRE(f.ok());
    for (const int i : {0, 1, 3}) {
        CHECK(frustum::row(e->matrix(), i) == close(frustum::row(f->matrix(), i), tight<T>()));
    }
    CHECK(frustum::planes(*e).near.abcd == close(frustum::planes(*f).near.abcd, loose<T>()));
    CHECK(max_diff(frustum::row(e->matrix(), 2), frustum::row(f->matrix(), 2)) > 1e-6);
    CHECK(inverse_residual(*e) <= 256 * eps<T>()); // crop's bound: J is crop's kind of map
}

TEST_CASE_TEMPLATE("jitter: errors, exact texts", T, float, double) {
    const MatrixPair<T> pair = camera<T>(DepthRange::ZeroToOne);
    CHECK(frustum::jitter(pair, T(0.25), T(0), T(0), T(720)).error() ==
          "frustum::jitter(): offsets must be finite and image sizes finite and > 0, got dx_px=0.25 dy_px=0 "
          "width_px=0 height_px=720");
    CHECK(frustum::jitter(pair, std::numeric_limits<T>::infinity(), T(0), T(1280), T(720)).error() ==
          "frustum::jitter(): offsets must be finite and image sizes finite and > 0, got dx_px=inf dy_px=0 "
          "width_px=1280 height_px=720");
}

} // TEST_SUITE
