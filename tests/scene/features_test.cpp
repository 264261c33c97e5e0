// glTF features a viewer is expected to have, loaded from the small files of
// tests/data/gltf-features (scripts/make_feature_gltf.py): unlit materials,
// texCoord sets, KHR_texture_transform, EXT_mesh_gpu_instancing, morph
// default weights, alpha modes, and the refusal of an unsupported required
// extension. The pictures are checked in tests/gl/render_features_test.cpp.
#include "../skips.hpp"
#include "helpers.hpp"

#include <doctest/doctest.h>

#include <scene/load_gltf.hpp>
#include <support/child_process.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

using scene_test::Json;

std::string feature_path(const std::string& name) {
    return std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-features/" + name;
}

scene::Scene load(const std::string& name) {
    auto loaded = scene::load_gltf(feature_path(name));
    REQUIRE_MESSAGE(loaded.ok(), loaded.error());
    return std::move(*loaded);
}

const scene::Instance& instance_named(const scene::Scene& s, const std::string& name) {
    for (const scene::Instance& instance : s.instances) {
        if (instance.node_name == name) {
            return instance;
        }
    }
    FAIL("no instance " << name);
    return s.instances.front();
}

const scene::Primitive& primitive_of(const scene::Scene& s, const std::string& node) {
    return s.meshes[static_cast<std::size_t>(instance_named(s, node).mesh)].primitives.front();
}

// The error of loading feature file `name` after `change`.
std::string error_after(const std::string& name, void (*change)(Json&)) {
    scene_test::TempDir dir;
    Json gltf = scene_test::read_json(feature_path(name));
    change(gltf);
    const auto path = dir.path() / name;
    scene_test::write_text(path, gltf.dump());
    auto loaded = scene::load_gltf(path.string());
    REQUIRE_FALSE(loaded.ok());
    return loaded.error();
}

// The quad's uv per vertex as scripts/make_feature_gltf.py writes them.
const glm::vec2 kQuadUv[6] = {{0, 1}, {1, 1}, {1, 0}, {0, 1}, {1, 0}, {0, 0}};

} // namespace

TEST_SUITE("scene") {

TEST_CASE("KHR_materials_unlit: the material is marked unlit, also when the file requires it") {
    const scene::Scene s = load("unlit.gltf");
    REQUIRE(s.materials.size() == 2);
    CHECK_FALSE(s.materials[0].unlit);
    CHECK(s.materials[1].unlit);
}

TEST_CASE("texCoord 1: the primitive carries the TEXCOORD_1 set its material reads") {
    const scene::Scene s = load("texcoord1.gltf");
    const scene::Primitive& quad = primitive_of(s, "quad");
    REQUIRE(quad.texcoords.size() == 6);
    for (std::size_t v = 0; v < 6; ++v) {
        CAPTURE(v);
        CHECK(quad.texcoords[v] == kQuadUv[v]); // not TEXCOORD_0's constant (0.9, 0.5)
    }
}

TEST_CASE("KHR_texture_transform: offset, rotation and scale applied as T R S, its texCoord overriding") {
    const scene::Scene s = load("texture_transform.gltf");
    const scene::Primitive& moved = primitive_of(s, "quad");
    REQUIRE(moved.texcoords.size() == 6);
    const scene::Primitive& turned = primitive_of(s, "turned");
    REQUIRE(turned.texcoords.size() == 6);
    for (std::size_t v = 0; v < 6; ++v) {
        CAPTURE(v);
        const glm::vec2 uv = kQuadUv[v];
        // offset (0.5, 0) through TEXCOORD_1 (the extension's texCoord).
        CHECK(moved.texcoords[v].x == doctest::Approx(uv.x + 0.5f));
        CHECK(moved.texcoords[v].y == doctest::Approx(uv.y));
        // scale (2, 3), then rotation pi/2 (u' = -v, v' = u), then offset (0.25, 0.5).
        CHECK(turned.texcoords[v].x == doctest::Approx(0.25f - 3.0f * uv.y).epsilon(1e-5));
        CHECK(turned.texcoords[v].y == doctest::Approx(0.5f + 2.0f * uv.x).epsilon(1e-5));
    }
}

TEST_CASE("a textured material whose texCoord set the primitive lacks reads no texcoords (not TEXCOORD_0)") {
    scene_test::TempDir dir;
    Json gltf = scene_test::read_json(feature_path("texcoord1.gltf"));
    gltf["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_1");
    const auto path = dir.path() / "texcoord1.gltf";
    scene_test::write_text(path, gltf.dump());
    auto loaded = scene::load_gltf(path.string());
    REQUIRE_MESSAGE(loaded.ok(), loaded.error());
    CHECK(loaded->meshes[0].primitives[0].texcoords.empty());
}

TEST_CASE("EXT_mesh_gpu_instancing: one instance per TRANSLATION/ROTATION/SCALE element") {
    const scene::Scene s = load("instancing.gltf");
    REQUIRE(s.instances.size() == 3);
    const float x[3] = {-0.6f, 0.0f, 0.6f};
    const float scale_y[3] = {1.0f, 2.0f, 1.0f};
    for (int i = 0; i < 3; ++i) {
        CAPTURE(i);
        const scene::Instance& instance = s.instances[static_cast<std::size_t>(i)];
        CHECK(instance.mesh == 0);
        CHECK(instance.node_name == "row");
        CHECK(instance.world[3].x == doctest::Approx(x[i]));
        CHECK(instance.world[1].y == doctest::Approx(scale_y[i]));
        CHECK(instance.world[0].x == doctest::Approx(1.0f));
    }
    CHECK(s.world_bounds.max.y == doctest::Approx(0.3f)); // the tall middle one
}

TEST_CASE("EXT_mesh_gpu_instancing: bad attributes are named") {
    CHECK(error_after("instancing.gltf", [](Json& g) {
              g["nodes"][1]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] = 0;
          }).find("node 1 EXT_mesh_gpu_instancing SCALE (accessor 0) has 6 elements but the other attributes "
                  "have 3") != std::string::npos);
    CHECK(error_after("instancing.gltf", [](Json& g) {
              g["nodes"][1]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["ROTATION"] = 99;
          }).find("node 1 EXT_mesh_gpu_instancing ROTATION uses accessor 99 but the file has") != std::string::npos);
}

TEST_CASE("morph targets: mesh.weights move POSITION at load, node.weights override them") {
    const scene::Scene s = load("morph.gltf");
    REQUIRE(s.instances.size() == 2);
    const scene::Primitive& moved = primitive_of(s, "moved");
    const scene::Primitive& kept = primitive_of(s, "kept");
    CHECK(instance_named(s, "moved").mesh != instance_named(s, "kept").mesh);
    for (std::size_t v = 0; v < moved.positions.size(); ++v) {
        CAPTURE(v);
        CHECK(moved.positions[v].x == doctest::Approx(kept.positions[v].x + 0.5f));
        CHECK(moved.positions[v].y == doctest::Approx(kept.positions[v].y));
        CHECK(std::abs(kept.positions[v].x) == doctest::Approx(0.2f));
    }
}

TEST_CASE("morph targets: weights that do not match the targets are named") {
    CHECK(error_after("morph.gltf", [](Json& g) { g["nodes"][2]["weights"] = {0.0, 1.0}; })
              .find("node 2 has 2 morph weights but its mesh has 1 morph targets") != std::string::npos);
    CHECK(error_after("morph.gltf", [](Json& g) { g["meshes"][0]["weights"] = {1.0, 1.0}; })
              .find("mesh 0 has 2 morph weights but its mesh has 1 morph targets") != std::string::npos);
}

TEST_CASE("alphaMode and alphaCutoff are read (MASK's cutoff defaults to 0.5)") {
    const scene::Scene s = load("alpha.gltf");
    REQUIRE(s.materials.size() == 3);
    CHECK(s.materials[0].alpha_mode == scene::AlphaMode::Blend);
    CHECK(s.materials[1].alpha_mode == scene::AlphaMode::Opaque);
    CHECK(s.materials[2].alpha_mode == scene::AlphaMode::Mask);
    CHECK(s.materials[2].alpha_cutoff == doctest::Approx(0.5f));
}

TEST_CASE("a required extension that is not supported is refused by name before parsing") {
    auto loaded = scene::load_gltf(feature_path("unsupported_required.gltf"));
    REQUIRE_FALSE(loaded.ok());
    CHECK(loaded.error() == "scene::load_gltf(): " + feature_path("unsupported_required.gltf") +
                                ": the file requires glTF extension KHR_materials_variants, which is not "
                                "supported (supported: EXT_mesh_gpu_instancing, EXT_meshopt_compression, "
                                "KHR_draco_mesh_compression, KHR_materials_unlit, KHR_mesh_quantization, "
                                "KHR_texture_transform)");
}

TEST_CASE("the generated files are what scripts/make_feature_gltf.py writes, and the folders hold nothing else") {
    const std::string python = support::find_on_path("python3");
    if (python.empty()) {
        test_skips::skip("python3 is not available");
        return;
    }
    scene_test::TempDir dir;
    support::Launch launch; // tests/support's runner: at most 120 s, then a failure naming the command
    launch.args = {std::string(FRUSTUM_SOURCE_DIR) + "/scripts/make_feature_gltf.py", dir.path().string()};
    const support::Outcome made = support::run(python, launch);
    REQUIRE_MESSAGE(made.exit_status == 0, made.err);
    const std::filesystem::path repository(FRUSTUM_SOURCE_DIR);
    std::size_t compared = 0;
    for (const std::string folder : {"tests/data/gltf-features", "tests/data/gltf-models", "tests/fuzz/corpus/gltf"}) {
        CAPTURE(folder);
        for (const auto& entry : std::filesystem::directory_iterator(dir.path() / folder)) {
            const std::string name = entry.path().filename().string();
            CAPTURE(name);
            CHECK(scene_test::read_bytes(entry.path()) == scene_test::read_bytes(repository / folder / name));
            ++compared;
        }
    }
    CHECK(compared == 9 + 19 + 7);
    // The two data folders hold only generated files (and their README).
    for (const char* folder : {"tests/data/gltf-features", "tests/data/gltf-models"}) {
        for (const auto& entry : std::filesystem::directory_iterator(repository / folder)) {
            const std::string name = entry.path().filename().string();
            CAPTURE(name);
            CHECK((name == "README.md" || std::filesystem::exists(dir.path() / folder / name)));
        }
    }
}

} // TEST_SUITE
