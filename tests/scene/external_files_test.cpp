// Good files in other layouts: external .bin and image files inside the
// model's folder, images in bufferViews, and .glb containers.
#include "helpers.hpp"
#include "scene_checks.hpp"

#include "scene/load_gltf.hpp"

#include <doctest/doctest.h>

#include <filesystem>

using scene_test::Bytes;
using scene_test::Json;

namespace {

namespace fs = std::filesystem;

using scene_test::load_ok;

void check_same_box(const scene::Scene& loaded) {
    const scene::Scene reference = load_ok(scene_test::model_path("box.gltf"));
    REQUIRE(loaded.meshes.size() == 1);
    CHECK(loaded.meshes[0].primitives[0].positions == reference.meshes[0].primitives[0].positions);
    CHECK(loaded.meshes[0].primitives[0].normals == reference.meshes[0].primitives[0].normals);
    CHECK(loaded.meshes[0].primitives[0].indices == reference.meshes[0].primitives[0].indices);
    REQUIRE(loaded.instances.size() == 1);
    CHECK(loaded.instances[0].world == reference.instances[0].world);
}

} // namespace

TEST_SUITE("scene") {

TEST_CASE("external .bin files inside the model folder load") {
    scene_test::TempDir dir;
    Json gltf = scene_test::read_json(scene_test::model_path("box.gltf"));
    const Bytes bytes = scene_test::buffer0(gltf);

    fs::create_directories(dir.path() / "data");
    scene_test::write_bytes(dir.path() / "data" / "box data.bin", bytes);
    gltf["buffers"][0]["uri"] = "data/box%20data.bin"; // percent-encoded space
    scene_test::write_text(dir.path() / "box.gltf", gltf.dump());
    check_same_box(load_ok(dir.path() / "box.gltf"));

    gltf["buffers"][0]["uri"] = "./data/box data.bin";
    scene_test::write_text(dir.path() / "dot.gltf", gltf.dump());
    check_same_box(load_ok(dir.path() / "dot.gltf"));
}

TEST_CASE("an external PNG and a PNG in a bufferView decode") {
    scene_test::TempDir dir;
    Json gltf = scene_test::read_json(scene_test::model_path("box_textured.gltf"));
    const std::string uri = gltf["images"][0]["uri"];
    fs::create_directories(dir.path() / "textures");
    scene_test::write_bytes(dir.path() / "textures" / "logo.png",
                            scene_test::base64_decode(uri.substr(uri.find(',') + 1)));

    Json external = gltf;
    external["images"][0]["uri"] = "textures/logo.png";
    scene_test::write_text(dir.path() / "external.gltf", external.dump());
    const scene::Scene from_file = load_ok(dir.path() / "external.gltf");

    Json embedded = gltf;
    scene_test::image0_into_buffer_view(embedded);
    scene_test::write_text(dir.path() / "embedded.gltf", embedded.dump());
    const scene::Scene from_view = load_ok(dir.path() / "embedded.gltf");

    const scene::Scene reference = load_ok(scene_test::model_path("box_textured.gltf"));
    for (const scene::Scene* s : {&from_file, &from_view}) {
        REQUIRE(s->images.size() == 1);
        CHECK(s->images[0].width == 4);
        CHECK(s->images[0].height == 4);
        CHECK(s->images[0].rgba == reference.images[0].rgba);
        CHECK(s->materials[0].base_color_texture == 0);
    }
}

TEST_CASE("GLB: the box and the torus (image in a bufferView) load like their .gltf") {
    scene_test::TempDir dir;
    const Json box = scene_test::read_json(scene_test::model_path("box.gltf"));
    scene_test::write_bytes(dir.path() / "box.glb", scene_test::make_glb(box, scene_test::buffer0(box)));
    check_same_box(load_ok(dir.path() / "box.glb"));

    Json torus = scene_test::read_json(scene_test::model_path("torus.gltf"));
    scene_test::image0_into_buffer_view(torus);
    scene_test::write_bytes(dir.path() / "torus.glb", scene_test::make_glb(torus, scene_test::buffer0(torus)));
    const scene::Scene s = load_ok(dir.path() / "torus.glb");
    const scene::Scene reference = load_ok(scene_test::model_path("torus.gltf"));
    REQUIRE(s.images.size() == 1);
    CHECK(s.images[0].width == 4);
    CHECK(s.images[0].height == 4);
    CHECK(s.images[0].rgba == reference.images[0].rgba);
    CHECK(s.cameras.size() == 1);
    CHECK(s.meshes[0].primitives[0].positions.size() == 49u * 33u);
    CHECK(s.meshes[0].primitives[0].positions == reference.meshes[0].primitives[0].positions);
    // The generator's own .glb (image in the BIN chunk) too.
    const scene::Scene packed = load_ok(scene_test::model_path("torus.glb"));
    CHECK(packed.meshes[0].primitives[0].positions == reference.meshes[0].primitives[0].positions);
    CHECK(packed.images[0].rgba == reference.images[0].rgba);
}

TEST_CASE("GLB: a chunk of unknown type after BIN is ignored") {
    scene_test::TempDir dir;
    const Json box = scene_test::read_json(scene_test::model_path("box.gltf"));
    Bytes glb = scene_test::make_glb(box, scene_test::buffer0(box));
    const Bytes extra = {4, 0, 0, 0, 'X', 'T', 'R', 'A', 1, 2, 3, 4};
    glb.insert(glb.end(), extra.begin(), extra.end());
    const std::uint32_t total = std::uint32_t(glb.size());
    for (int i = 0; i < 4; ++i) glb[8 + i] = std::uint8_t(total >> (8 * i));
    scene_test::write_bytes(dir.path() / "extra.glb", glb);
    check_same_box(load_ok(dir.path() / "extra.glb"));
}

} // TEST_SUITE
