// Valid glTF 2.0 that the loader must take although it draws nothing of the
// part in question (the glTF-Validator reports these files clean): a
// primitive without POSITION, a skin without inverseBindMatrices, an
// animation channel target without node, an image no texture draws that is
// not PNG or JPEG. Each is made by mutating a vendored sample.
#include "helpers.hpp"

#include "scene/load_gltf.hpp"

#include <doctest/doctest.h>

using scene_test::Bytes;
using scene_test::Json;

namespace {

frustum::Result<scene::Scene> load_json(const scene_test::TempDir& dir, const Json& gltf) {
    const auto path = dir.path() / "model.gltf";
    scene_test::write_text(path, gltf.dump());
    return scene::load_gltf(path.string());
}

frustum::Result<scene::Scene> load_glb(const scene_test::TempDir& dir, const Json& gltf) {
    const auto path = dir.path() / "model.glb";
    Json moved = gltf;
    const Bytes bin = scene_test::buffer0(moved);
    scene_test::write_bytes(path, scene_test::make_glb(moved, bin));
    return scene::load_gltf(path.string());
}

std::size_t primitive_count(const scene::Scene& scene) {
    std::size_t count = 0;
    for (const scene::Mesh& mesh : scene.meshes) count += mesh.primitives.size();
    return count;
}

} // namespace

TEST_CASE("a primitive without POSITION is skipped, the others drawn (glTF 2.0 3.7.2.1)") {
    scene_test::TempDir dir;
    Json gltf = scene_test::read_json(scene_test::model_path("box.gltf"));
    Json primitive = gltf["meshes"][0]["primitives"][0];
    primitive["attributes"].erase("POSITION");
    gltf["meshes"][0]["primitives"].push_back(primitive);
    frustum::Result<scene::Scene> scene = load_json(dir, gltf);
    REQUIRE_MESSAGE(scene.ok(), scene.error());
    CHECK(primitive_count(*scene) == 1);
    CHECK(scene->meshes[0].primitives[0].positions.size() == 24);
}

TEST_CASE("a skin without inverseBindMatrices loads, in .gltf and .glb, as the skin with them") {
    scene_test::TempDir dir;
    const Json original = scene_test::read_json(scene_test::model_path("skin.gltf"));
    REQUIRE(original.contains("animations"));
    Json gltf = original;
    gltf["skins"][0].erase("inverseBindMatrices");
    frustum::Result<scene::Scene> reference = load_json(dir, original);
    REQUIRE_MESSAGE(reference.ok(), reference.error());
    for (const bool glb : {false, true}) {
        CAPTURE(glb);
        frustum::Result<scene::Scene> scene = glb ? load_glb(dir, gltf) : load_json(dir, gltf);
        REQUIRE_MESSAGE(scene.ok(), scene.error());
        REQUIRE(primitive_count(*scene) == primitive_count(*reference));
        CHECK(scene->meshes[0].primitives[0].positions == reference->meshes[0].primitives[0].positions);
        CHECK(scene->instances.size() == reference->instances.size());
    }
}

TEST_CASE("an animation channel target without node (KHR_animation_pointer) loads") {
    scene_test::TempDir dir;
    Json gltf = scene_test::read_json(scene_test::model_path("skin.gltf"));
    Json& target = gltf["animations"][0]["channels"][0]["target"];
    target.erase("node");
    target["path"] = "pointer";
    target["extensions"] = {{"KHR_animation_pointer", {{"pointer", "/nodes/0/rotation"}}}};
    gltf["extensionsUsed"] = {"KHR_animation_pointer"};
    frustum::Result<scene::Scene> scene = load_json(dir, gltf);
    REQUIRE_MESSAGE(scene.ok(), scene.error());
    CHECK(primitive_count(*scene) == 1);
}

TEST_CASE("an image no texture draws need not decode; one a texture draws must") {
    scene_test::TempDir dir;
    Json gltf = scene_test::read_json(scene_test::model_path("box_textured.gltf"));
    // A WebP image, as EXT_texture_webp names beside a PNG fallback (tinygltf
    // does not read image/webp data uris), and RIFF bytes labelled PNG
    // (the decoder refuses them).
    const std::string riff = "UklGRhwAAABXRUJQVlA4TA8AAAAv/8AfAAcQ/Y/+ByKi/wEA";
    gltf["images"].push_back({{"uri", "data:image/webp;base64," + riff}});
    gltf["images"].push_back({{"uri", "data:image/png;base64," + riff}});
    frustum::Result<scene::Scene> scene = load_json(dir, gltf);
    REQUIRE_MESSAGE(scene.ok(), scene.error());
    REQUIRE(scene->images.size() == 3);
    CHECK(scene->images[0].rgba.size() == std::size_t(scene->images[0].width) * scene->images[0].height * 4);
    CHECK(scene->images[1].rgba.empty());
    CHECK(scene->images[2].rgba.empty());

    gltf["textures"][0]["source"] = 1;
    frustum::Result<scene::Scene> webp = load_json(dir, gltf);
    REQUIRE_FALSE(webp.ok());
    CHECK(webp.error().find("image 1 (uri \"data:image/webp;base64,") != std::string::npos);
    CHECK(webp.error().find("could not be read") != std::string::npos);

    gltf["textures"][0]["source"] = 2;
    frustum::Result<scene::Scene> riff_png = load_json(dir, gltf);
    REQUIRE_FALSE(riff_png.ok());
    CHECK(riff_png.error().find("image 2: the image is neither PNG nor JPEG (first bytes 52 49 46)") !=
          std::string::npos);
}
