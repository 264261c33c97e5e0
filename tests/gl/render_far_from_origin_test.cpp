// A scene 5 km from the world origin renders every effect as it does at the
// origin (tests/math/far_from_origin_test.cpp has the library side): the
// whole scene (instances, cameras, mirror, lens spot, bounds) is moved by
// (5000, 120, -2000) m, as a glTF parent node with that translation would,
// and each effect's picture is compared with the one at the origin.
#include "render_test_support.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <map>

namespace {

constexpr int kWidthPx = 160;
constexpr int kHeightPx = 90;
// float positions 5 km out are good to 5e-4 m: edges move by a pixel here
// and there (BoxTextured: at most 24 of the 14400 pixels differ by more than
// 24 LSB, measured). The showcase's mirror sits millimetres in front of its
// frame, and at that precision some lens and recursion tiles draw the frame
// over it (186 pixels, measured). Pixels allowed to differ by more than
// kToleranceLsb, per scene:
constexpr int kToleranceLsb = 24;
constexpr int kMaxDifferentBox = kWidthPx * kHeightPx / 200;      // 0.5%
constexpr int kMaxDifferentShowcase = kWidthPx * kHeightPx / 50;  // 2%

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
    auto env = gl_test::make_environment(gl::Backend::Egl);
    if (!env) {
        env = gl_test::make_environment(gl::Backend::OsMesa);
    }
    if (!env) {
        return;
    }
    const std::filesystem::path samples(FRUSTUM_SAMPLES_DIR);
    const struct {
        std::filesystem::path file;
        int max_different_px;
    } cases[] = {{std::filesystem::path(FRUSTUM_SOURCE_DIR) / "assets/showcase.gltf", kMaxDifferentShowcase},
                 {samples / "BoxTextured/BoxTextured.gltf", kMaxDifferentBox}};
    for (const auto& c : cases) {
        const std::filesystem::path& file = c.file;
        const int max_different_px = c.max_different_px;
        INFO(file.filename().string());
        const auto scene = scene::load_gltf(file.string());
        REQUIRE_MESSAGE(scene.ok(), scene.error());
        scene::Scene moved = *scene;
        move_scene(moved, glm::vec3(5000.0f, 120.0f, -2000.0f));
        const auto at_origin = render_all(*env, *scene);
        const auto far_out = render_all(*env, moved);
        for (render::Effect effect : render::kAllEffects) {
            INFO(render::to_string(effect));
            const auto diff = image::compare(far_out.at(effect), at_origin.at(effect), kToleranceLsb);
            REQUIRE(diff.ok());
            MESSAGE(file.filename().string() << " " << render::to_string(effect) << ": " << diff->pixels_over
                                             << " of " << kWidthPx * kHeightPx << " pixels differ");
            CHECK(diff->pixels_over <= max_different_px);
            if (diff->pixels_over > max_different_px) {
                render_test::save_failure("far-from-origin-" + file.stem().string() + "-" +
                                              std::string(render::to_string(effect)),
                                          at_origin.at(effect), far_out.at(effect));
            }
        }
    }
}

} // TEST_SUITE
