// One frame as data: the untouched camera is the scene's pair exactly, tile
// counts are capped, the inset's place; make_cameras keeps the aspect.
#include "../plan/showcase.hpp"

#include <doctest/doctest.h>
// Approx epsilon of these float results: 2 float ulps relative (2 x 1.19e-7), doctest's
// default (1.19e-5) being 100; each passes at 2 ulps (measured: tightened until one failed).
static constexpr double kFloatTwoUlps = 2.4e-7;

#include <window/frame.hpp>

#include <frustum/queries.hpp>

namespace {

bool same(const frustum::MatrixPair<float>& a, const frustum::MatrixPair<float>& b) {
    return a.matrix() == b.matrix() && a.inverse() == b.inverse() && a.depth() == b.depth();
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("with no camera input the frame uses the scene's main camera pair exactly") {
    const scene::Scene& scene = render_test::showcase();
    const plan::Cameras cameras = render_test::showcase_cameras();
    window::ViewerState state;
    const auto frame = window::make_frame(state, cameras, {}, scene.world_bounds, 256, 144);
    REQUIRE_MESSAGE(frame.ok(), frame.error());
    CHECK(same(frame->cameras.main.pair, cameras.main.pair));
    CHECK(same(frame->cameras.overview.pair, cameras.overview.pair));
    CHECK(frame->text.empty());

    state.orbit = window::orbit_from_pair(cameras.main.pair, scene.world_bounds);
    state.show_help = true;
    const auto orbiting = window::make_frame(state, cameras, {}, scene.world_bounds, 256, 144);
    REQUIRE_MESSAGE(orbiting.ok(), orbiting.error());
    CHECK(orbiting->cameras.main.name == "orbit");
    CHECK_FALSE(orbiting->text.empty());
}

TEST_CASE("an orbit replaces an orthographic camera's perspective twin too") {
    const scene::Scene& scene = render_test::showcase();
    const plan::Cameras shown = render_test::showcase_cameras();
    plan::Cameras cameras = shown;
    cameras.perspective_twin = plan::NamedCamera{"main (perspective twin)", shown.overview.pair};
    window::ViewerState state;
    state.effect = plan::Effect::Lens;
    const auto still = window::make_frame(state, cameras, {}, scene.world_bounds, 256, 144);
    REQUIRE_MESSAGE(still.ok(), still.error());
    CHECK(same(plan::cameras_for(plan::Effect::Lens, still->cameras).main.pair, shown.overview.pair));
    state.orbit = window::orbit_from_pair(shown.main.pair, scene.world_bounds);
    const auto orbiting = window::make_frame(state, cameras, {}, scene.world_bounds, 256, 144);
    REQUIRE_MESSAGE(orbiting.ok(), orbiting.error());
    CHECK_FALSE(orbiting->cameras.perspective_twin.has_value());
    CHECK(plan::cameras_for(plan::Effect::Lens, orbiting->cameras).main.name == "orbit");
}

TEST_CASE("tile counts are capped at one pixel per tile") {
    window::ViewerState state;
    state.tile_columns = 16;
    state.tile_rows = 16;
    const auto frame = window::make_frame(state, render_test::showcase_cameras(), {}, scene::Bounds{}, 10, 4);
    REQUIRE_MESSAGE(frame.ok(), frame.error());
    CHECK(frame->options.tile_columns == 10);
    CHECK(frame->options.tile_rows == 4);
}

TEST_CASE("the inset: a third of the width, top-right, the framebuffer's aspect") {
    const auto rect = window::inset_rect(960, 540);
    REQUIRE(rect);
    CHECK(rect->width == 320);
    CHECK(rect->height == 180);
    CHECK(rect->x + rect->width == 960 - 8);
    CHECK(rect->y + rect->height == 540 - 8);
    CHECK_FALSE(window::inset_rect(95, 540));
    CHECK_FALSE(window::inset_rect(960, 63));
    CHECK(window::inset_effect(plan::Effect::Plain) == plan::Effect::Frustum);
    CHECK(window::inset_effect(plan::Effect::Frustum) == plan::Effect::Plain);
}

TEST_CASE("make_cameras: a scene camera takes the image's aspect, so a square stays square") {
    const scene::Scene& scene = render_test::showcase();
    const int index = *plan::find_camera(render_test::showcase(), std::nullopt);
    // A square window: the main camera's 16:9 gives way, so a square in the
    // picture stays square: |m00| == |m11| for a symmetric perspective
    // (the view is rigid, so compare the scaled rows' lengths).
    const auto square = plan::make_cameras(scene, index, 300, 300);
    REQUIRE_MESSAGE(square.ok(), square.error());
    for (const plan::NamedCamera* camera : {&square->main, &square->overview}) {
        const glm::mat4& m = camera->pair.matrix();
        const float row0 = glm::length(glm::vec3(m[0][0], m[1][0], m[2][0]));
        const float row1 = glm::length(glm::vec3(m[0][1], m[1][1], m[2][1]));
        CAPTURE(camera->name);
        CHECK(row0 == doctest::Approx(row1).epsilon(1e-4));
    }
}

TEST_CASE("camera_pair: an orthographic camera keeps ymag and widens to the image's aspect") {
    scene::Camera camera;
    camera.name = "ortho";
    camera.kind = scene::Camera::Kind::Orthographic;
    camera.xmag = 1.0f; // a square camera ...
    camera.ymag = 1.0f;
    camera.znear_m = 0.1f;
    camera.zfar_m = 10.0f;
    for (const float aspect : {16.0f / 9.0f, 1.0f, 0.5f}) {
        // ... in a 16:9, square or tall image: one world unit is as many
        // pixels across as it is up, so nothing is stretched.
        const auto pair = plan::camera_pair(camera, aspect);
        REQUIRE_MESSAGE(pair.ok(), pair.error());
        const glm::mat4& m = pair->matrix();
        CAPTURE(aspect);
        CHECK(m[1][1] == doctest::Approx(1.0f).epsilon(kFloatTwoUlps));         // ymag 1: y in [-1, 1]
        CHECK(m[0][0] * aspect == doctest::Approx(1.0f).epsilon(kFloatTwoUlps)); // x in [-aspect, aspect]
    }
}

} // TEST_SUITE
