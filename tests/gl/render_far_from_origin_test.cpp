// A scene 5 km from the world origin renders every effect as it does at the
// origin (tests/math/far_from_origin_test.cpp has the library side): the
// whole scene (instances, cameras, mirror, lens spot, bounds) is moved by
// (5000, 120, -2000) m, as a glTF parent node with that translation would,
// and each effect's picture is compared with the one at the origin.
//
// Georeferenced files (UTM, ECEF) go further: the showcase and a generated
// model under a parent node at (500000, 0, 5000000) m and (6378137, 0, 0) m,
// written as glTF files, load relative to their centre (scene::Scene::origin_m)
// and render every effect as at the origin.
#include "render_test_support.hpp"

#include <scene/load_gltf.hpp>
#include <support/temp_dir.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace {

constexpr int kWidthPx = 160;
constexpr int kHeightPx = 90;
// float positions 5 km out are good to 5e-4 m: edges move by a pixel here
// and there. The showcase's mirror sits millimetres in front of its frame,
// and at that precision some lens and recursion tiles draw the frame over
// it. Pixels differing by more than kToleranceLsb, measured per scene and
// effect (llvmpipe, 160x90; the lens 119 to 186 as its tiles changed):
constexpr int kToleranceLsb = 24;
using Measured = std::map<plan::Effect, int>;
const Measured kShowcaseMeasuredPx = {
    {plan::Effect::Plain, 16},  {plan::Effect::Mirror, 16},    {plan::Effect::Tiles, 13},
    {plan::Effect::Frustum, 117}, {plan::Effect::Curved, 16},  {plan::Effect::Lens, 186},
    {plan::Effect::NonAffine, 11}, {plan::Effect::Portal, 37}, {plan::Effect::Recursion, 82}};
const Measured kBoxMeasuredPx = {
    {plan::Effect::Plain, 1},    {plan::Effect::Mirror, 1},   {plan::Effect::Tiles, 7},
    {plan::Effect::Frustum, 24}, {plan::Effect::Curved, 3},   {plan::Effect::Lens, 2},
    {plan::Effect::NonAffine, 7}, {plan::Effect::Portal, 12}, {plan::Effect::Recursion, 7}};

// The bound: what was measured plus a quarter, at least 4 pixels (another
// rasterizer's rounding of a few edge pixels).
int max_different_px(const Measured& measured, plan::Effect effect) {
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
std::map<plan::Effect, image::Image> render_all(const gl_test::Environment& env, scene::Scene scene) {
    const render_test::DerivedScene derived = render_test::derive_scene(env, scene, kWidthPx, kHeightPx);
    std::map<plan::Effect, image::Image> pictures;
    for (plan::Effect effect : plan::kAllEffects) {
        INFO(plan::to_string(effect));
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
        for (plan::Effect effect : plan::kAllEffects) {
            INFO(plan::to_string(effect));
            const int max_different = max_different_px(c.measured_px, effect);
            const auto diff = image::compare(far_out.at(effect), at_origin.at(effect), kToleranceLsb);
            REQUIRE(diff.ok());
            MESSAGE(file.filename().string() << " " << plan::to_string(effect) << ": " << diff->pixels_over
                                             << " of " << kWidthPx * kHeightPx << " pixels differ");
            CHECK(diff->pixels_over <= max_different);
            if (diff->pixels_over > max_different) {
                render_test::save_failure("far-from-origin-" + file.stem().string() + "-" +
                                              std::string(plan::to_string(effect)),
                                          at_origin.at(effect), far_out.at(effect));
            }
        }
    }
}

namespace {

// `file` (a .gltf with embedded buffers and images) with its scene's root
// nodes under one new root node translated by `offset_m`, written to `out`.
void write_georeferenced(const std::filesystem::path& file, const glm::dvec3& offset_m,
                         const std::filesystem::path& out) {
    std::ifstream in(file);
    REQUIRE(in);
    nlohmann::json gltf = nlohmann::json::parse(in);
    const int scene = gltf.value("scene", 0);
    nlohmann::json& roots = gltf["scenes"][scene]["nodes"];
    gltf["nodes"].push_back({{"name", "georeference"},
                             {"translation", {offset_m.x, offset_m.y, offset_m.z}},
                             {"children", roots}});
    roots = nlohmann::json::array({gltf["nodes"].size() - 1});
    support::write_file(out, gltf.dump());
}

// Pixels over kToleranceLsb at (500000, 0, 5000000) m and (6378137, 0, 0) m,
// the larger of the two, measured (llvmpipe, 160x90): the scene keeps the
// same coordinates relative to its rounded centre, so only float rounding of
// the sub-metre remainder differs.
const Measured kShowcaseGeoMeasuredPx = {
    {plan::Effect::Plain, 0},   {plan::Effect::Mirror, 0},    {plan::Effect::Tiles, 0},
    {plan::Effect::Frustum, 0}, {plan::Effect::Curved, 0},    {plan::Effect::Lens, 1},
    {plan::Effect::NonAffine, 0}, {plan::Effect::Portal, 0}, {plan::Effect::Recursion, 1}};
const Measured kBoxGeoMeasuredPx = {
    {plan::Effect::Plain, 0},   {plan::Effect::Mirror, 0},    {plan::Effect::Tiles, 0},
    {plan::Effect::Frustum, 0}, {plan::Effect::Curved, 0},    {plan::Effect::Lens, 0},
    {plan::Effect::NonAffine, 0}, {plan::Effect::Portal, 0}, {plan::Effect::Recursion, 0}};

} // namespace

TEST_CASE("every effect at UTM and ECEF coordinates looks as it does at the origin") {
    auto env = gl_test::make_any_environment();
    if (!env) {
        return;
    }
    const std::filesystem::path source(FRUSTUM_SOURCE_DIR);
    const struct {
        std::filesystem::path file;
        const Measured& measured_px;
    } cases[] = {{source / "assets/showcase.gltf", kShowcaseGeoMeasuredPx},
                 {source / "tests/data/gltf-models/box_textured.gltf", kBoxGeoMeasuredPx}};
    const glm::dvec3 offsets_m[] = {{500000.0, 0.0, 5000000.0}, {6378137.0, 0.0, 0.0}};
    support::TempDir dir;
    for (const auto& c : cases) {
        INFO(c.file.filename().string());
        const auto scene = scene::load_gltf(c.file.string());
        REQUIRE_MESSAGE(scene.ok(), scene.error());
        CHECK(scene->origin_m == glm::dvec3(0.0)); // near the origin: kept as it is
        const auto at_origin = render_all(*env, *scene);
        for (const glm::dvec3& offset_m : offsets_m) {
            std::ostringstream where;
            where << "offset (" << offset_m.x << ", " << offset_m.y << ", " << offset_m.z << ") m";
            INFO(where.str());
            const std::filesystem::path moved_file = dir / ("georeferenced-" + c.file.filename().string());
            write_georeferenced(c.file, offset_m, moved_file);
            const auto moved = scene::load_gltf(moved_file.string());
            REQUIRE_MESSAGE(moved.ok(), moved.error());
            // Relative to its centre rounded to whole metres: the offset plus
            // the origin picture's centre, rounded.
            const glm::dvec3 centre_m = 0.5 * (glm::dvec3(scene->world_bounds.min) + glm::dvec3(scene->world_bounds.max));
            CHECK(moved->origin_m == glm::round(offset_m + centre_m));
            CHECK(glm::length(glm::dvec3(moved->world_bounds.max)) < 1000.0); // the GPU sees small numbers
            const auto far_out = render_all(*env, *moved);
            for (plan::Effect effect : plan::kAllEffects) {
                INFO(plan::to_string(effect));
                const int max_different = max_different_px(c.measured_px, effect);
                const auto diff = image::compare(far_out.at(effect), at_origin.at(effect), kToleranceLsb);
                REQUIRE(diff.ok());
                MESSAGE(c.file.filename().string() << " " << where.str() << " " << plan::to_string(effect) << ": "
                                                   << diff->pixels_over << " of " << kWidthPx * kHeightPx
                                                   << " pixels differ");
                CHECK(diff->pixels_over <= max_different);
            }
        }
    }
}

} // TEST_SUITE
