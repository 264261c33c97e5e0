// Issue 33 on the CPU: file cameras without a usable far plane get one
// derived from the scene (plan::derived_far_m(), make_cameras()), the
// recursion ends cleanly where nothing is left to see (plan_views()), and
// the derived mirror and the links stand where a camera inside the scene
// sees them (place_mirror(), view_anchor()) in the generated room and street.
#include "../sample_files.hpp"

#include <doctest/doctest.h>

#include <frustum/lens.hpp>
#include <frustum/projection.hpp>
#include <frustum/queries.hpp>
#include <plan/camera.hpp>
#include <plan/mirror_geometry.hpp>
#include <plan/mirror_placement.hpp>
#include <plan/scene_fit.hpp>
#include <plan/view_links.hpp>
#include <plan/view_tree.hpp>
#include <scene/load_gltf.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace {

constexpr int kW = 160, kH = 90;

scene::Scene load(const char* name) {
    auto s = scene::load_gltf(test_samples::model_path(name));
    REQUIRE_MESSAGE(s.ok(), s.error());
    REQUIRE(s->cameras.size() == 1);
    return std::move(*s);
}

plan::Cameras cameras_of(const scene::Scene& s) {
    auto cameras = plan::make_cameras(s, 0, kW, kH);
    REQUIRE_MESSAGE(cameras.ok(), cameras.error());
    return std::move(*cameras);
}

bool contains(const std::optional<std::string>& text, const std::string& part) {
    return text && text->find(part) != std::string::npos;
}

} // namespace

TEST_SUITE("plan") {

TEST_CASE("a file camera without zfar, or with zfar 2e7 x znear, gets a far plane that holds the whole scene") {
    struct Case {
        const char* file;
        const char* note; // what far_note must say
    };
    for (const Case c : {Case{"room_no_zfar.gltf", "no zfar"}, Case{"street.gltf", "zfar 1e+06 is 2e+07 x its znear 0.05"}}) {
        CAPTURE(c.file);
        const scene::Scene s = load(c.file);
        const plan::Cameras cameras = cameras_of(s);
        REQUIRE(cameras.far_note);
        CHECK(contains(cameras.far_note, c.note));
        const auto far_m = frustum::far_distance(cameras.main.pair);
        REQUIRE_MESSAGE(far_m.ok(), far_m.error());
        const float near_m = s.cameras[0].znear_m;
        CHECK(*far_m / near_m <= 1.01f * plan::kMaxFarPerNear);
        // Every corner of the scene's bounds is nearer than the far plane, the farthest within 5% + rounding.
        const glm::vec3 eye(s.cameras[0].camera_to_world[3]);
        float reach_m = 0.0f;
        for (const glm::vec3& corner : scene::corners(s.world_bounds)) {
            reach_m = std::max(reach_m, glm::length(corner - eye));
        }
        CHECK(*far_m >= reach_m);
        CHECK(*far_m <= 1.06f * reach_m);
        // The effects that need a finite far plane take it.
        plan::NonAffineOptions base;
        auto nonaffine = plan::fit_non_affine(cameras.main.pair, s.world_bounds, base, plan::EffectFit{});
        CHECK_MESSAGE(nonaffine.ok(), nonaffine.error());
        auto lens = plan::fit_lens(cameras.main.pair, s.lens, s.world_bounds, plan::EffectFit{}, 2.0f);
        REQUIRE_MESSAGE(lens.ok(), lens.error());
        auto tiles = frustum::lens_tiles(cameras.main.pair, *lens, kW, kH, 4, 4);
        CHECK_MESSAGE(tiles.ok(), tiles.error());
        // An explicit value beyond that far plane is still a usage error naming it.
        plan::EffectFit beyond;
        beyond.pivot_m = 2.0f * *far_m;
        auto refused = plan::fit_non_affine(cameras.main.pair, s.world_bounds, base, beyond);
        REQUIRE_FALSE(refused.ok());
        CHECK(refused.error().find("--pivot") == 0);
    }
    // A far plane the pair holds (room.gltf: zfar 50 = 500 x znear) is kept;
    // one at 5e4 x znear, which the library still reads as finite, is replaced.
    const scene::Scene room = load("room.gltf");
    const plan::Cameras kept = cameras_of(room);
    CHECK_FALSE(kept.far_note);
    CHECK(frustum::far_distance(kept.main.pair).value() == doctest::Approx(50.0f).epsilon(1e-3));
    CHECK_FALSE(plan::derived_far_m(room.cameras[0], room.world_bounds));
    scene::Camera far_out = room.cameras[0];
    far_out.zfar_m = 5e4f * far_out.znear_m;
    const auto derived = plan::derived_far_m(far_out, room.world_bounds);
    REQUIRE(derived);
    CHECK(*derived < 50.0f);
}

TEST_CASE("a derived far plane is at most 1e4 x the near one, and the note says what it cuts") {
    scene::Scene s = load("room_no_zfar.gltf");
    s.cameras[0].znear_m = 1e-4f; // 1e4 x znear = 1 m, inside the room
    const plan::Cameras cameras = cameras_of(s);
    CHECK(contains(cameras.far_note, "cut to 1e+04 x znear"));
    const auto far_m = frustum::far_distance(cameras.main.pair);
    REQUIRE_MESSAGE(far_m.ok(), far_m.error());
    CHECK(*far_m == doctest::Approx(1.0f).epsilon(1e-3));
}

TEST_CASE("the recursion ends cleanly at the first level whose link leaves nothing of the view: the levels before draw") {
    // Two facing mirrors 3 m either side of the view axis, 100 m long, seen
    // by a camera whose far plane is 20 m out: from the fourth bounce on,
    // the mirror plane has the whole cropped view on its near side
    // (frustum::clip_oblique: "clip plane leaves no part of the frustum
    // visible"), which used to fail the whole frame.
    auto camera = frustum::perspective<float>(1.0f, 16.0f / 9.0f, 0.1f, 20.0f, frustum::DepthRange::ZeroToOne);
    REQUIRE(camera.ok());
    plan::ViewLink left, right;
    left.half_width_m = right.half_width_m = 50.0f;
    left.half_height_m = right.half_height_m = 1.0f;
    left.entry.origin = glm::vec3(-3.0f, 0.0f, -50.5f);
    left.entry.x = glm::vec3(0.0f, 0.0f, -1.0f); // normal +x, into the corridor
    left.entry.y = glm::vec3(0.0f, 1.0f, 0.0f);
    right.entry.origin = glm::vec3(3.0f, 0.0f, -50.5f);
    right.entry.x = glm::vec3(0.0f, 0.0f, 1.0f); // normal -x
    right.entry.y = glm::vec3(0.0f, 1.0f, 0.0f);
    auto plan = plan::plan_views(*camera, {left, right}, {8, kW, kH, plan::ViewBounds::Tight});
    REQUIRE_MESSAGE(plan.ok(), plan.error());
    REQUIRE(plan->empty_from_level);
    const int empty = *plan->empty_from_level;
    CHECK(empty == 4);
    int deepest = 0;
    for (const plan::ViewNode& node : plan->nodes) {
        deepest = std::max(deepest, node.level);
    }
    CHECK(deepest == empty - 1); // every level before it has views
    auto nodes = plan::plan_view_tree(*camera, {left, right}, {8, kW, kH, plan::ViewBounds::Tight});
    REQUIRE(nodes.ok());
    CHECK(nodes->size() == plan->nodes.size());
}

TEST_CASE("seen from inside the room and the street, the derived mirror stands in front of the eye, in view, facing it") {
    for (const std::string file : {"room.gltf", "room_no_zfar.gltf", "street.gltf"}) {
        CAPTURE(file);
        scene::Scene s = load(file.c_str());
        const plan::Cameras cameras = cameras_of(s);
        const std::vector<scene::Bounds> boxes = plan::instance_boxes(s);
        // The old rule's floor, under the model's bounds, is below the floor the camera stands on.
        const auto placed = plan::place_mirror(s, plan::MirrorRequest{}, &cameras.main.pair);
        CHECK(contains(placed, "in front of the camera (the eye is inside the model's bounds)"));
        REQUIRE(s.mirror);
        const scene::MirrorRect& m = *s.mirror;
        const glm::vec3 eye(s.cameras[0].camera_to_world[3]);
        const glm::vec3 center = m.corner + 0.5f * (m.a1 + m.a2);
        CHECK(glm::dot(glm::cross(m.a1, m.a2), eye - center) > 0.0f); // faces the eye
        // The middle half of the frame each way: a quarter of the grid's rays hit it.
        const float seen = plan::fraction_in_view(cameras.main.pair, m);
        CHECK(seen >= 0.2f);
        CHECK(seen <= 0.3f);
        // It stands in the open: its centre is in no box of the scene.
        for (const scene::Bounds& box : boxes) {
            CHECK_FALSE(plan::eye_inside(center, box));
        }
        // The portal pair and the facing mirrors stand in view too: each quad covers 5% of the frame or more.
        auto portal = plan::place_portal_pair(cameras.main.pair, s.world_bounds, boxes);
        auto facing = plan::place_facing_links(cameras.main.pair, s.world_bounds, plan::LinkSet::Mirrors, boxes);
        REQUIRE(portal.ok());
        REQUIRE(facing.ok());
        for (const std::vector<plan::ViewLink>* links : {&*portal, &*facing}) {
            for (const plan::ViewLink& link : *links) {
                const std::vector<glm::vec3> q = link.quad();
                scene::MirrorRect rect;
                rect.corner = q[0];
                rect.a1 = q[1] - q[0];
                rect.a2 = q[3] - q[0];
                const auto on_screen = plan::mirror_screen_rect(rect, cameras.main.pair, kW, kH);
                REQUIRE(on_screen);
                CHECK(on_screen->width * on_screen->height >= kW * kH / 20);
            }
        }
    }
}

TEST_CASE("seen from outside, a floor the camera sees stays the derived mirror") {
    for (const std::string file : {"box.gltf", "torus.gltf"}) {
        CAPTURE(file);
        auto loaded = scene::load_gltf(test_samples::model_path(file));
        REQUIRE(loaded.ok());
        scene::Scene s = std::move(*loaded);
        const auto index = plan::find_camera(s, std::nullopt);
        REQUIRE(index.ok());
        auto cameras = plan::make_cameras(s, *index, kW, kH);
        REQUIRE(cameras.ok());
        CHECK_FALSE(cameras->far_note);
        const auto placed = plan::place_mirror(s, plan::MirrorRequest{}, &cameras->main.pair);
        CHECK(contains(placed, "mirror: floor under the model"));
        REQUIRE(s.mirror);
        CHECK(plan::fraction_in_view(cameras->main.pair, *s.mirror) >= plan::kMinFloorInView);
    }
}

TEST_CASE("seen from outside looking up, where the floor is out of view, the derived mirror stands in front of the eye") {
    auto loaded = scene::load_gltf(test_samples::model_path("box.gltf"));
    REQUIRE(loaded.ok());
    scene::Scene s = std::move(*loaded);
    // From 5 m in front of the unit cube, at its height, looking 30 degrees up: the floor under it is below the frame.
    auto projection = frustum::perspective<float>(0.8f, 16.0f / 9.0f, 0.1f, 100.0f, frustum::DepthRange::ZeroToOne);
    auto view = frustum::look_at<float>(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f, 5.0f * std::tan(0.5236f), 0.0f),
                                        glm::vec3(0.0f, 1.0f, 0.0f));
    REQUIRE(projection.ok());
    REQUIRE(view.ok());
    const frustum::MatrixPair<float> camera = frustum::compose(*projection, *view);
    float floor_side_m = 0.0f;
    {
        scene::Scene without_camera = s; // the old rule's floor, for comparison
        plan::place_mirror(without_camera, plan::MirrorRequest{});
        REQUIRE(without_camera.mirror);
        CHECK(plan::fraction_in_view(camera, *without_camera.mirror) < plan::kMinFloorInView);
        floor_side_m = glm::length(without_camera.mirror->a1);
    }
    const auto placed = plan::place_mirror(s, plan::MirrorRequest{}, &camera);
    CHECK(contains(placed, "in front of the camera (a floor under the model would be out of view)"));
    REQUIRE(s.mirror);
    CHECK(glm::length(s.mirror->a1) != doctest::Approx(floor_side_m));
    CHECK(plan::fraction_in_view(camera, *s.mirror) >= 0.2f);
}

} // TEST_SUITE
