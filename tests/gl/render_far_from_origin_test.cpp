// A scene 5 km from the world origin renders every effect as it does at the
// origin (tests/math/far_from_origin_test.cpp has the library side): the
// whole scene (instances, cameras, mirror, lens spot, bounds) is moved by
// (5000, 120, -2000) m, as a glTF parent node with that translation would,
// and each effect's picture is compared with the one at the origin.
#include "render_test_support.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <map>

namespace {

constexpr int kWidthPx = 160;
constexpr int kHeightPx = 90;
// float positions 5 km out are good to 5e-4 m: edges move by a pixel here
// and there. The showcase's mirror sits millimetres in front of its frame,
// and at that precision some lens and recursion tiles draw the frame over
// it. Pixels differing by more than kToleranceLsb, measured per scene and
// effect (llvmpipe, 160x90; the lens 119 to 186 as its tiles changed):
constexpr int kToleranceLsb = 24;
using Measured = std::map<render::Effect, int>;
const Measured kShowcaseMeasuredPx = {
    {render::Effect::Plain, 16},  {render::Effect::Mirror, 16},    {render::Effect::Tiles, 13},
    {render::Effect::Frustum, 117}, {render::Effect::Curved, 16},  {render::Effect::Lens, 186},
    {render::Effect::NonAffine, 11}, {render::Effect::Portal, 37}, {render::Effect::Recursion, 82}};
const Measured kBoxMeasuredPx = {
    {render::Effect::Plain, 1},    {render::Effect::Mirror, 1},   {render::Effect::Tiles, 7},
    {render::Effect::Frustum, 24}, {render::Effect::Curved, 3},   {render::Effect::Lens, 2},
    {render::Effect::NonAffine, 7}, {render::Effect::Portal, 12}, {render::Effect::Recursion, 7}};

// The bound: what was measured plus a quarter, at least 4 pixels (another
// rasterizer's rounding of a few edge pixels).
int max_different_px(const Measured& measured, render::Effect effect) {
    const int px = measured.at(effect);
    return px + std::max(4, (px + 3) / 4);
}

void move_scene(scene::Scene& s, const glm::vec3& offset_m) {
    const glm::mat4 move = glm::translate(glm::mat4(1.0f), offset_m);
    for (auto& instance : s.instances) {
        instance.world = move * instance.world;
    }
    for (auto& camera : s.cameras) {
        camera.camera_to_world = move * camera.camera_to_world;
    }
    if (s.mirror) {
        s.mirror->corner += offset_m;
    }
    if (s.lens) {
        s.lens->center += offset_m;
    }
    s.world_bounds.min += offset_m;
    s.world_bounds.max += offset_m;
}

// Every effect of `scene` with its derived camera and parameters.
std::map<render::Effect, image::Image> render_all(const gl_test::Environment& env, scene::Scene scene) {
    const render_test::DerivedScene derived = render_test::derive_scene(env, scene, kWidthPx, kHeightPx);
    std::map<render::Effect, image::Image> pictures;
    for (render::Effect effect : render::kAllEffects) {
        INFO(render::to_string(effect));
        auto picture = derived.renderer->render(effect, derived.cameras, derived.options);
        REQUIRE_MESSAGE(picture.ok(), picture.error());
        pictures.emplace(effect, std::move(*picture));
    }
    return pictures;
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("every effect 5 km from the origin looks as it does at the origin") {
    auto env = gl_test::make_any_environment();
    if (!env) {
        return;
    }
    const std::filesystem::path models = std::filesystem::path(FRUSTUM_SOURCE_DIR) / "tests/data/gltf-models";
    const struct {
        std::filesystem::path file;
        const Measured& measured_px;
    } cases[] = {{std::filesystem::path(FRUSTUM_SOURCE_DIR) / "assets/showcase.gltf", kShowcaseMeasuredPx},
                 {models / "box_textured.gltf", kBoxMeasuredPx}};
    for (const auto& c : cases) {
        const std::filesystem::path& file = c.file;
        INFO(file.filename().string());
        const auto scene = scene::load_gltf(file.string());
        REQUIRE_MESSAGE(scene.ok(), scene.error());
        scene::Scene moved = *scene;
        move_scene(moved, glm::vec3(5000.0f, 120.0f, -2000.0f));
        const auto at_origin = render_all(*env, *scene);
        const auto far_out = render_all(*env, moved);
        for (render::Effect effect : render::kAllEffects) {
            INFO(render::to_string(effect));
            const int max_different = max_different_px(c.measured_px, effect);
            const auto diff = image::compare(far_out.at(effect), at_origin.at(effect), kToleranceLsb);
            REQUIRE(diff.ok());
            MESSAGE(file.filename().string() << " " << render::to_string(effect) << ": " << diff->pixels_over
                                             << " of " << kWidthPx * kHeightPx << " pixels differ");
            CHECK(diff->pixels_over <= max_different);
            if (diff->pixels_over > max_different) {
                render_test::save_failure("far-from-origin-" + file.stem().string() + "-" +
                                              std::string(render::to_string(effect)),
                                          at_origin.at(effect), far_out.at(effect));
            }
        }
    }
}

} // TEST_SUITE
