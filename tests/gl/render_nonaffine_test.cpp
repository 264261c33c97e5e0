// The non-affine effect (paper §6, eq. 36 per vertex) against the plain
// frame (the camera's own planes) and against the CPU ray cast, and the
// zero-denominator remedy: cull + subdivide.
#include "render_test_support.hpp"

#include <frustum/queries.hpp>
#include <gl/offscreen_target.hpp>
#include <render/non_affine_pass.hpp>
#include <reference/non_affine_reference.hpp>

namespace {

// The ray cast costs pixels x triangles: keep it small (16:9 like the camera).
constexpr int kCastWidthPx = 160;
constexpr int kCastHeightPx = 90;

struct Drawn {
    image::Image picture;
    render::NonAffineStats stats;
};

Drawn draw_non_affine(const render_test::RenderEnvironment& r, const frustum::NonAffineFrustum<float>& f,
                      const plan::NonAffineOptions& o, int width_px, int height_px) {
    const gl::Functions& fn = r.env->fn;
    auto depth = render::DepthPolicy::apply(fn, *r.env->context, render::DepthPath::ClipControlWhenAvailable);
    REQUIRE_MESSAGE(depth.ok(), depth.error());
    auto frame = gl::OffscreenTarget::create(fn, {width_px, height_px});
    REQUIRE_MESSAGE(frame.ok(), frame.error());
    const render::PassContext ctx = r.renderer->pass_context(*depth, render::Lighting{});
    const auto geometry = plan::WorldGeometry::from_scene(render_test::showcase());
    auto stats = render::draw_non_affine_frame(ctx, *frame, geometry, f, o);
    REQUIRE_MESSAGE(stats.ok(), stats.error());
    auto picture = frame->read_rgba8();
    REQUIRE_MESSAGE(picture.ok(), picture.error());
    return {std::move(*picture), *stats};
}

frustum::NonAffineFrustum<float> crossed_slits(const plan::Cameras& cameras) {
    auto f = plan::crossed_slits_frustum(cameras.main.pair, plan::NonAffineOptions{},
                                         frustum::DepthRange::ZeroToOne);
    REQUIRE_MESSAGE(f.ok(), f.error());
    return *f;
}

render_test::MaskedDiff versus(const image::Image& a, const image::Image& b) {
    return render_test::compare_masked(a, b, render_test::Mask(a.rgba.size() / 4, true), 8);
}

double fraction_over(const render_test::MaskedDiff& d) { return static_cast<double>(d.pixels_over) / d.compared; }

} // namespace

TEST_SUITE("gl") {

TEST_CASE("eq. 36 with the camera's own six planes renders the plain frame") {
    RENDER_TEST_ANY_RENDERER(r);
    const auto cameras = render_test::showcase_cameras();
    const auto p = frustum::planes(cameras.main.pair);
    REQUIRE(p.far.has_value());
    const auto eye_to_centre = frustum::to_point(frustum::key_points(cameras.main.pair).center, 1e-6f);
    auto f = frustum::NonAffineFrustum<float>::from_planes(p.left.flipped(), p.right.flipped(), p.bottom.flipped(),
                                                          p.top.flipped(), p.near.flipped(), p.far->flipped(),
                                                          glm::vec3(eye_to_centre), frustum::DepthRange::ZeroToOne);
    REQUIRE_MESSAGE(f.ok(), f.error());
    plan::NonAffineOptions o;
    o.max_edge_m = 0.0f; // a matrix frustum keeps straight edges straight
    const Drawn drawn = draw_non_affine(*r, *f, o, render_test::kWidthPx, render_test::kHeightPx);
    const image::Image plain = r->render(plan::Effect::Plain, cameras, render_test::options());
    // For a symmetric camera both denominators are proportional to the eye
    // depth, so eq. 36 is the projection itself and w = -(d_l + d_r + d_t +
    // d_b) / 2 makes the interpolation perspective-correct; only the depth
    // buffer differs (s is linear in distance). Tolerance 2 LSB; up to 0.1%
    // of the pixels may differ more (edges within rounding of a pixel centre).
    // Measured at 256x144: 1 pixel.
    const auto diff = image::compare(plain, drawn.picture, 2);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    MESSAGE("camera planes through eq. 36 vs plain: max " << diff->max_abs << ", " << diff->pixels_over
                                                          << " pixels over 2 LSB");
    CHECK(drawn.stats.culled == 0);
    CHECK(diff->pixels_over <= render_test::kWidthPx * render_test::kHeightPx / 1000);
    if (diff->pixels_over > render_test::kWidthPx * render_test::kHeightPx / 1000) {
        render_test::save_failure("nonaffine-camera-planes", plain, drawn.picture);
    }
}

TEST_CASE("the crossed-slits frame matches the ray cast once culled and subdivided") {
    RENDER_TEST_ANY_RENDERER(r);
    const auto cameras = render_test::showcase_cameras(kCastWidthPx, kCastHeightPx);
    const auto f = crossed_slits(cameras);
    const auto geometry = plan::WorldGeometry::from_scene(render_test::showcase());
    const image::Image exact = reference::ray_cast_non_affine(geometry, f, render::Lighting{}, render::kClearColor,
                                                              kCastWidthPx, kCastHeightPx);
    const render_test::Mask all(static_cast<std::size_t>(kCastWidthPx * kCastHeightPx), true);
    CHECK(render_test::count_not_sky(exact, all) > kCastWidthPx * kCastHeightPx / 3); // measured 45%

    plan::NonAffineOptions o;
    const Drawn remedied = draw_non_affine(*r, f, o, kCastWidthPx, kCastHeightPx);
    CHECK(render_test::count_not_sky(remedied.picture, all) > kCastWidthPx * kCastHeightPx / 3);
    // Left: pixels on silhouettes where the GPU's straight edges between
    // vertices 0.25 m apart leave the curves eq. 36 makes of them, and the
    // pieces within a triangle of the slit that culling drops. Bound: mean
    // 0.5 LSB, 0.5% of the pixels over 8 LSB. Measured at 160x90: mean 0.04,
    // 0.04% (6 pixels).
    const auto d = versus(remedied.picture, exact);
    MESSAGE("cull + subdivide 0.25 m vs ray cast: mean " << d.mean_abs << ", " << 100.0 * fraction_over(d) << "%");
    CHECK(d.mean_abs < 0.5);
    CHECK(fraction_over(d) < 0.005);
    if (d.mean_abs >= 0.5 || fraction_over(d) >= 0.005) {
        render_test::save_failure("nonaffine-vs-ray-cast", remedied.picture, exact);
    }
}

TEST_CASE("eq. 36's zero denominators: naive tears the frame, culling leaves holes, subdivision closes them") {
    RENDER_TEST_ANY_RENDERER(r);
    const auto cameras = render_test::showcase_cameras(kCastWidthPx, kCastHeightPx);
    const auto f = crossed_slits(cameras);
    const plan::NonAffineOptions defaults;
    const auto geometry = plan::WorldGeometry::from_scene(render_test::showcase());

    // Where: the floor triangles that reach across the slit. The degenerate
    // set of d_l + d_r is the plane through the slit (the line where the left
    // and right planes meet), 2.6 m in front of the eye; the visible floor
    // starts about 3.1 m out, so its nearest rows of triangles straddle it.
    int straddling = 0, degenerate = 0;
    for (const plan::WorldPrimitive& p : geometry.primitives) {
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            float low = 1e9f, high = -1e9f;
            bool any = false;
            for (std::size_t v = 0; v < 3; ++v) {
                const glm::vec3 d = f.denominators(p.vertices[p.indices[t + v]].position);
                low = std::min(low, d.x), high = std::max(high, d.x);
                any = any || !(d.x < -defaults.guard_m && d.y < -defaults.guard_m && d.z < -defaults.guard_m);
            }
            straddling += low < 0.0f && high > 0.0f;
            degenerate += any;
        }
    }
    MESSAGE(straddling << " triangles straddle d_l + d_r = 0, " << degenerate << " have a degenerate vertex");
    CHECK(straddling > 0);

    const image::Image exact = reference::ray_cast_non_affine(geometry, f, render::Lighting{}, render::kClearColor,
                                                              kCastWidthPx, kCastHeightPx);
    plan::NonAffineOptions naive = defaults;
    naive.cull = false;
    naive.max_edge_m = 0.0f;
    plan::NonAffineOptions cull_only = defaults;
    cull_only.max_edge_m = 0.0f;
    const Drawn torn = draw_non_affine(*r, f, naive, kCastWidthPx, kCastHeightPx);
    const Drawn holes = draw_non_affine(*r, f, cull_only, kCastWidthPx, kCastHeightPx);
    const Drawn closed = draw_non_affine(*r, f, defaults, kCastWidthPx, kCastHeightPx);
    CHECK(torn.stats.culled == 0);
    CHECK(holes.stats.culled == degenerate); // exactly the triangles with a degenerate vertex
    CHECK(closed.stats.culled > 0);
    const auto d_torn = versus(torn.picture, exact), d_holes = versus(holes.picture, exact);
    const auto d_closed = versus(closed.picture, exact);
    MESSAGE("pixels over 8 LSB: naive " << 100.0 * fraction_over(d_torn) << "%, cull only "
                                        << 100.0 * fraction_over(d_holes) << "%, cull + subdivide "
                                        << 100.0 * fraction_over(d_closed) << "%");
    // Measured at 160x90: 88%, 7.2%, 0.04%; 20 triangles straddle, 29 culled.
    CHECK(fraction_over(d_torn) > 0.3);
    CHECK(fraction_over(d_holes) > 0.02);
    CHECK(fraction_over(d_holes) > 4.0 * fraction_over(d_closed));
}

} // TEST_SUITE
