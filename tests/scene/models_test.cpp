// Every generated model of tests/data/gltf-models (scripts/gltf_models.py)
// loads to what its generator wrote: the loader features a model from the
// wild exercises, checked on files the project made, with exact values.
#include "../sample_files.hpp"
#include "helpers.hpp"
#include "scene_checks.hpp"

#include "scene/load_gltf.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <set>

using scene_test::model_path;

namespace {

using scene_test::instance_named;
using scene_test::load_ok;

// Float values the generator wrote from doubles: a few float steps.
bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-6f) { return scene_test::near(a, b, tolerance); }
bool near(const glm::mat4& a, const glm::mat4& b, float tolerance = 1e-6f) { return scene_test::near(a, b, tolerance); }

// The RGBA8 texel (x, y) of image 0, y = 0 the image's top row.
image::Rgba texel(const scene::Scene& s, int x, int y) {
    const image::Image& im = s.images.at(0);
    const std::size_t at = (std::size_t(y) * std::size_t(im.width) + std::size_t(x)) * 4;
    return {im.rgba[at], im.rgba[at + 1], im.rgba[at + 2], im.rgba[at + 3]};
}

} // namespace

TEST_SUITE("scene") {

TEST_CASE("every generated model loads with the expected mesh, instance, camera and image counts") {
    const scene_test::ExpectedModel models[] = {
        {"box.gltf", 1, 1, 0, 0},           {"box_textured.gltf", 1, 1, 0, 1},
        {"box_vertex_colors.gltf", 1, 1, 0, 0}, {"cameras.gltf", 1, 1, 2, 0},
        {"index_types.gltf", 3, 3, 0, 0},   {"interleaved.gltf", 1, 1, 0, 1},
        {"morph.gltf", 1, 1, 0, 0},         {"multiple_scenes.gltf", 2, 1, 0, 0},
        {"nodes.gltf", 1, 4, 0, 0},         {"primitive_modes.gltf", 7, 7, 0, 0},
        {"room.gltf", 7, 10, 1, 0},         {"room_no_zfar.gltf", 7, 10, 1, 0},
        {"skin.gltf", 1, 1, 0, 0},          {"sparse.gltf", 1, 1, 0, 0},
        {"street.gltf", 4, 21, 1, 0},
        {"torus.gltf", 1, 1, 1, 1},         {"torus.glb", 1, 1, 1, 1},
        {"triangle.gltf", 1, 1, 0, 0},      {"triangle_without_indices.gltf", 1, 1, 0, 0},
    };
    // The table names every file of the folder, and nothing else.
    std::set<std::string> listed, found;
    for (const scene_test::ExpectedModel& e : models) listed.insert(e.name);
    for (const auto& file : test_samples::gltf_files_under(test_samples::models_folder())) {
        found.insert(file.filename().string());
    }
    CHECK(listed == found);
    for (const scene_test::ExpectedModel& expected : models) {
        CAPTURE(expected.name);
        const scene::Scene s = scene_test::load_with_shape(model_path(expected.name), expected.counts);
        CHECK(s.world_bounds.min.x < s.world_bounds.max.x);
    }
}

TEST_CASE("box: the parent node matrix becomes the instance's world transform") {
    const scene::Scene s = load_ok(model_path("box.gltf"));
    REQUIRE(s.instances.size() == 1);
    // -90 degrees about X: +Y goes to -Z, +Z to +Y.
    const glm::mat4 turned(glm::vec4(1, 0, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 0, 1));
    CHECK(s.instances[0].world == turned);
    CHECK(s.world_bounds.min == glm::vec3(-0.5f));
    CHECK(s.world_bounds.max == glm::vec3(0.5f));
    const scene::Primitive& p = s.meshes[0].primitives[0];
    CHECK(p.positions.size() == 24);
    CHECK(p.indices.size() == 36);
    // The first face is +Z: its normal, and its first vertex at the bottom left.
    CHECK(p.normals[0] == glm::vec3(0, 0, 1));
    CHECK(p.positions[0] == glm::vec3(-0.5f, -0.5f, 0.5f));
    REQUIRE(s.materials.size() == 1);
    CHECK(s.materials[0].base_color_factor.r == 0.8f);
}

TEST_CASE("index types: UNSIGNED_BYTE, UNSIGNED_SHORT and UNSIGNED_INT give the same indices") {
    const scene::Scene s = load_ok(model_path("index_types.gltf"));
    REQUIRE(s.meshes.size() == 3);
    const std::vector<std::uint32_t>& reference = s.meshes[0].primitives[0].indices;
    REQUIRE(reference.size() == 36);
    CHECK(*std::max_element(reference.begin(), reference.end()) == 23);
    CHECK(s.meshes[1].primitives[0].indices == reference);
    CHECK(s.meshes[2].primitives[0].indices == reference);
    CHECK(near(glm::vec3(instance_named(s, "uint").world[3]), glm::vec3(1.5f, 0, 0)));
}

TEST_CASE("primitive modes: all seven, the line and point modes without indices") {
    const scene::Scene s = load_ok(model_path("primitive_modes.gltf"));
    std::set<scene::PrimitiveMode> modes;
    for (const scene::Mesh& mesh : s.meshes) {
        for (const scene::Primitive& primitive : mesh.primitives) modes.insert(primitive.mode);
    }
    CHECK(modes.size() == 7);
    for (scene::PrimitiveMode mode : {scene::PrimitiveMode::Points, scene::PrimitiveMode::Lines,
                                      scene::PrimitiveMode::LineLoop, scene::PrimitiveMode::LineStrip,
                                      scene::PrimitiveMode::Triangles, scene::PrimitiveMode::TriangleStrip,
                                      scene::PrimitiveMode::TriangleFan}) {
        CHECK(modes.count(mode) == 1);
    }
    // POINTS (mesh 0) has no index accessor: 0..3.
    CHECK(s.meshes[0].primitives[0].indices == std::vector<std::uint32_t>{0, 1, 2, 3});
    CHECK(s.meshes[5].primitives[0].indices == std::vector<std::uint32_t>{0, 1, 3, 2}); // the strip's own
}

TEST_CASE("triangle without indices gets 0..n-1; the indexed one keeps its own") {
    CHECK(load_ok(model_path("triangle_without_indices.gltf")).meshes[0].primitives[0].indices ==
          std::vector<std::uint32_t>{0, 1, 2});
    const scene::Scene indexed = load_ok(model_path("triangle.gltf"));
    CHECK(indexed.meshes[0].primitives[0].indices == std::vector<std::uint32_t>{0, 1, 2});
    CHECK(indexed.meshes[0].primitives[0].normals.empty()); // flat-shaded by the renderer
}

TEST_CASE("multiple scenes: the default scene 1, or the scene asked for") {
    const scene::Scene by_default = load_ok(model_path("multiple_scenes.gltf"));
    REQUIRE(by_default.instances.size() == 1);
    CHECK(by_default.instances[0].mesh == 1);
    CHECK(by_default.world_bounds.min == glm::vec3(-0.5f));

    scene::LoadOptions first;
    first.scene_index = 0;
    const scene::Scene scene0 = load_ok(model_path("multiple_scenes.gltf"), first);
    REQUIRE(scene0.instances.size() == 1);
    CHECK(scene0.instances[0].mesh == 0);
    CHECK(scene0.meshes.size() == 2); // every mesh is loaded; instances pick
    CHECK(scene0.world_bounds.min == glm::vec3(0.0f));
}

TEST_CASE("cameras: perspective and orthographic with their node transforms") {
    const scene::Scene s = load_ok(model_path("cameras.gltf"));
    REQUIRE(s.cameras.size() == 2);
    const scene::Camera& p = s.cameras[0];
    CHECK(p.kind == scene::Camera::Kind::Perspective);
    CHECK(p.name == "perspective");
    CHECK(p.yfov_rad == 0.7f);
    REQUIRE(p.aspect.has_value());
    CHECK(*p.aspect == 1.5f);
    CHECK(p.znear_m == 0.01f);
    REQUIRE(p.zfar_m.has_value());
    CHECK(*p.zfar_m == 100.0f);
    const scene::Camera& o = s.cameras[1];
    CHECK(o.kind == scene::Camera::Kind::Orthographic);
    CHECK(o.xmag == 1.0f);
    CHECK(o.ymag == 1.0f);
    for (const scene::Camera& camera : s.cameras) {
        CHECK(glm::vec3(camera.camera_to_world[3]) == glm::vec3(0.5f, 0.5f, 3.0f));
    }
}

TEST_CASE("nodes: TRS with a quaternion, a matrix node and its child, one mesh four times") {
    const scene::Scene s = load_ok(model_path("nodes.gltf"));
    REQUIRE(s.instances.size() == 4);
    CHECK(instance_named(s, "base").world == glm::mat4(1.0f));
    const double half = 15.0 * M_PI / 180.0;
    const glm::quat q(float(std::cos(half)), float(-std::sin(half)), 0.0f, 0.0f); // w, x, y, z
    const glm::mat4 trs = glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0)) * glm::mat4_cast(q) *
                          glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.5f, 0.5f));
    CHECK(near(instance_named(s, "trs").world, trs));
    CHECK(glm::vec3(instance_named(s, "trs").world[3]) == glm::vec3(2, 0, 0)); // T * R * S: T untouched

    const float c = float(std::cos(5.0 * M_PI / 180.0)), sn = float(std::sin(5.0 * M_PI / 180.0));
    const glm::mat4 matrix(glm::vec4(1, 0, 0, 0), glm::vec4(0, c, sn, 0), glm::vec4(0, -sn, c, 0), glm::vec4(-2, 0, 0, 1));
    CHECK(near(instance_named(s, "matrix").world, matrix));
    // The child moves (0, 0, 1) in the matrix node's frame.
    CHECK(near(glm::vec3(instance_named(s, "leaf").world[3]), glm::vec3(-2.0f, -sn, c)));
    for (const scene::Instance& instance : s.instances) CHECK(instance.mesh == 0);
}

TEST_CASE("vertex colours: COLOR_0 as RGBA float, the position mapped to [0, 1]") {
    const scene::Scene s = load_ok(model_path("box_vertex_colors.gltf"));
    const scene::Primitive& p = s.meshes[0].primitives[0];
    REQUIRE(p.colors.size() == 24);
    for (std::size_t i = 0; i < p.colors.size(); ++i) {
        CHECK(glm::vec3(p.colors[i]) == p.positions[i] + glm::vec3(0.5f));
        CHECK(p.colors[i].a == 1.0f);
    }
}

TEST_CASE("sparse: the sparse values replace the dense ones, the bounds follow") {
    const scene::Scene s = load_ok(model_path("sparse.gltf"));
    const std::vector<glm::vec3>& positions = s.meshes[0].primitives[0].positions;
    REQUIRE(positions.size() == 8);
    CHECK(positions[0] == glm::vec3(0, 0, 0));     // untouched
    CHECK(positions[1] == glm::vec3(0.5f, 1, 0));  // sparse index 1
    CHECK(positions[3] == glm::vec3(1.5f, 2, 0));  // sparse index 3
    CHECK(positions[6] == glm::vec3(1.0f, -1, 0)); // sparse index 6
    CHECK(positions[7] == glm::vec3(1.5f, -0.5f, 0));
    CHECK(s.world_bounds.min == glm::vec3(0, -1, 0));
    CHECK(s.world_bounds.max == glm::vec3(1.5f, 2, 0));
}

TEST_CASE("morph: targets on POSITION and NORMAL applied with mesh.weights") {
    const scene::Scene s = load_ok(model_path("morph.gltf"));
    const scene::Primitive& p = s.meshes[0].primitives[0];
    REQUIRE(p.positions.size() == 4);
    // Weight 0.5 of +0.5 m on the top edge: 1.25 m tall.
    CHECK(p.positions[0] == glm::vec3(-0.5f, 0, 0));
    CHECK(p.positions[2] == glm::vec3(0.5f, 1.25f, 0));
    CHECK(p.positions[3] == glm::vec3(-0.5f, 1.25f, 0));
    // Weight 1 of (1, 0, 0) on the normals: (1, 0, 1) before normalization.
    REQUIRE(p.normals.size() == 4);
    for (const glm::vec3& n : p.normals) {
        CHECK(near(glm::normalize(n), glm::normalize(glm::vec3(1, 0, 1))));
    }
}

TEST_CASE("skin: the bind pose at the node, joints and weights not needed to draw") {
    const scene::Scene s = load_ok(model_path("skin.gltf"));
    REQUIRE(s.instances.size() == 1);
    CHECK(glm::vec3(s.instances[0].world[3]) == glm::vec3(0, 0, 0.5f));
    const scene::Primitive& p = s.meshes[0].primitives[0];
    CHECK(p.positions.size() == 40);
    CHECK(p.indices.size() == 4u * 8u * 6u);
    CHECK(near(s.world_bounds.min, glm::vec3(-0.25f, 0.0f, 0.25f)));
    CHECK(near(s.world_bounds.max, glm::vec3(0.25f, 2.0f, 0.75f)));
}

TEST_CASE("textures: the orientation PNG decodes with red at uv (0, 0), the image's top left") {
    for (const std::string file : {"box_textured.gltf", "interleaved.gltf", "torus.gltf", "torus.glb"}) {
        CAPTURE(file);
        const scene::Scene s = load_ok(model_path(file));
        scene_test::check_one_image(s, 4, 4);
        CHECK(texel(s, 0, 0) == image::Rgba{255, 0, 0, 255});     // top left: red
        CHECK(texel(s, 3, 0) == image::Rgba{0, 255, 0, 255});     // top right: green
        CHECK(texel(s, 0, 3) == image::Rgba{0, 0, 255, 255});     // bottom left: blue
        CHECK(texel(s, 3, 3) == image::Rgba{255, 255, 255, 255}); // bottom right: white
        CHECK(s.materials[0].base_color_texture == 0);
        // The +Z face's top-left corner (first face, vertex 3) has uv (0, 0).
        if (std::string(file) == "box_textured.gltf" || std::string(file) == "interleaved.gltf") {
            const scene::Primitive& p = s.meshes[0].primitives[0];
            CHECK(p.positions[3] == glm::vec3(-0.5f, 0.5f, 0.5f));
            CHECK(p.texcoords[3] == glm::vec2(0, 0));
            CHECK(p.texcoords[1] == glm::vec2(1, 1));
        }
    }
}

TEST_CASE("interleaved: one bufferView with byteStride reads as the packed box") {
    const scene::Scene a = load_ok(model_path("interleaved.gltf"));
    const scene::Scene b = load_ok(model_path("box_textured.gltf"));
    CHECK(a.meshes[0].primitives[0].positions == b.meshes[0].primitives[0].positions);
    CHECK(a.meshes[0].primitives[0].normals == b.meshes[0].primitives[0].normals);
    CHECK(a.meshes[0].primitives[0].texcoords == b.meshes[0].primitives[0].texcoords);
    CHECK(a.meshes[0].primitives[0].indices == b.meshes[0].primitives[0].indices);
}

TEST_CASE("torus: a few thousand triangles, the parent's scale on the mesh and on the camera's place only") {
    const scene::Scene s = load_ok(model_path("torus.gltf"));
    const scene::Primitive& p = s.meshes[0].primitives[0];
    CHECK(p.positions.size() == 49u * 33u);
    CHECK(p.indices.size() == 3u * 3072u);
    CHECK(near(s.world_bounds.max, glm::vec3(0.85f, 0.25f, 0.85f), 1e-5f));
    REQUIRE(s.cameras.size() == 1);
    const scene::Camera& camera = s.cameras[0];
    CHECK(camera.name == "camera 0"); // neither the camera nor its node is named
    CHECK(near(glm::vec3(camera.camera_to_world[3]), glm::vec3(0, 2, 3)));
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(std::abs(glm::length(glm::vec3(camera.camera_to_world[axis])) - 1.0f) < 1e-6f);
    }
    // Looking down at the origin: -Z of the camera along (0, -2, -3).
    CHECK(near(-glm::vec3(camera.camera_to_world[2]), glm::normalize(glm::vec3(0, -2, -3))));
    CHECK(camera.znear_m == 1.0f);
    REQUIRE(camera.zfar_m.has_value());
    CHECK(*camera.zfar_m == 10000.0f);
}

} // TEST_SUITE
