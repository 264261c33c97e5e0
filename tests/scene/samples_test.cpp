// Every Khronos sample of the external corpus (FRUSTUM_TEST_DATA/gltf-samples,
// not part of the repository: CTest's corpus-samples-load, a skip when
// FRUSTUM_TEST_DATA is not set) loads, with the expected content. The
// project's own models cover the same loader features in models_test.cpp.
#include "../sample_files.hpp"
#include "helpers.hpp"
#include "scene_checks.hpp"

#include "scene/load_gltf.hpp"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <set>

namespace {

using scene_test::instance_named;
using scene_test::load_ok;
using scene_test::near;

// The samples' values as printed to 6 significant digits; matrices built
// here from the same floats: a few float steps.
constexpr float kPrintedTolerance = 1e-4f;
constexpr float kMatrixTolerance = 1e-5f;

// FRUSTUM_TEST_DATA/gltf-samples/<model>/<model>.gltf
std::string sample(const std::filesystem::path& samples, const std::string& model) {
    return (samples / model / (model + ".gltf")).string();
}


} // namespace

TEST_SUITE("corpus-samples") {

TEST_CASE("every sample loads with the expected mesh and instance counts") {
    const auto folder = test_samples::corpus_folder("gltf-samples");
    if (!folder) return;
    const scene_test::ExpectedModel samples[] = {
        {"AnimatedTriangle", 1, 1, 0, 0}, {"Box", 1, 1, 0, 0},
        {"BoxAnimated", 2, 2, 0, 0},      {"BoxTextured", 1, 1, 0, 1},
        {"BoxVertexColors", 1, 1, 0, 0},  {"Cameras", 1, 1, 2, 0},
        {"Duck", 1, 1, 1, 1},             {"MeshPrimitiveModes", 7, 7, 0, 0},
        {"MultipleScenes", 2, 1, 0, 0},   {"OrientationTest", 13, 13, 0, 0},
        {"RiggedSimple", 1, 1, 0, 0},     {"SimpleMeshes", 1, 2, 0, 0},
        {"SimpleMorph", 1, 1, 0, 0},      {"SimpleSkin", 1, 1, 0, 0},
        {"SimpleSparseAccessor", 1, 1, 0, 0}, {"TextureCoordinateTest", 5, 5, 0, 1},
        {"Triangle", 1, 1, 0, 0},         {"TriangleWithoutIndices", 1, 1, 0, 0},
    };
    for (const scene_test::ExpectedModel& expected : samples) {
        CAPTURE(expected.name);
        const scene::Scene s = scene_test::load_with_shape(sample(*folder, expected.name), expected.counts);
        CHECK(s.world_bounds.min.x <= s.world_bounds.max.x);
    }
}

TEST_CASE("Duck: camera, decoded texture, node scale in the bounds") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene s = load_ok(sample(*samples, "Duck"));
    scene_test::check_one_image(s, 512, 512);
    REQUIRE(s.materials.size() == 1);
    CHECK(s.materials[0].name == "blinn3-fx");
    CHECK(s.materials[0].base_color_texture == 0);
    const scene::Primitive& primitive = s.meshes[0].primitives[0];
    CHECK(primitive.positions.size() == 2399);
    CHECK(primitive.indices.size() == 12636);
    CHECK(primitive.texcoords.size() == 2399);
    CHECK(primitive.normals.size() == 2399);
    CHECK(primitive.material == 0);

    REQUIRE(s.cameras.size() == 1);
    const scene::Camera& camera = s.cameras[0];
    CHECK(camera.kind == scene::Camera::Kind::Perspective);
    CHECK(camera.name == "camera 0"); // neither the camera nor its node is named
    CHECK(camera.yfov_rad == doctest::Approx(0.6605925559997559));
    REQUIRE(camera.aspect.has_value());
    CHECK(*camera.aspect == doctest::Approx(1.5));
    CHECK(camera.znear_m == doctest::Approx(1.0));
    REQUIRE(camera.zfar_m.has_value());
    CHECK(*camera.zfar_m == doctest::Approx(10000.0));
    // Parent scale 0.01 moves the camera but is stripped from its rotation.
    CHECK(near(glm::vec3(camera.camera_to_world[3]), glm::vec3(4.00113f, 4.63264f, -4.31078f), kPrintedTolerance));
    for (int axis = 0; axis < 3; ++axis) {
        CHECK(glm::length(glm::vec3(camera.camera_to_world[axis])) == doctest::Approx(1.0));
    }
    CHECK(near(glm::vec3(camera.camera_to_world[2]), glm::vec3(0.536475f, 0.621148f, -0.571288f), kPrintedTolerance));

    CHECK(near(s.world_bounds.min, glm::vec3(-0.6929850f, 0.0992937f, -0.6132820f), kPrintedTolerance));
    CHECK(near(s.world_bounds.max, glm::vec3(0.9617990f, 1.6397000f, 0.5392520f), kPrintedTolerance));
}

TEST_CASE("Cameras: perspective and orthographic with their node transforms") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene s = load_ok(sample(*samples, "Cameras"));
    REQUIRE(s.cameras.size() == 2);
    CHECK(s.cameras[0].kind == scene::Camera::Kind::Perspective);
    CHECK(s.cameras[0].yfov_rad == doctest::Approx(0.7));
    CHECK(s.cameras[0].znear_m == doctest::Approx(0.01));
    CHECK(s.cameras[1].kind == scene::Camera::Kind::Orthographic);
    CHECK(s.cameras[1].xmag == doctest::Approx(1.0));
    CHECK(s.cameras[1].ymag == doctest::Approx(1.0));
    REQUIRE(s.cameras[1].zfar_m.has_value());
    CHECK(*s.cameras[1].zfar_m == doctest::Approx(100.0));
    for (const scene::Camera& camera : s.cameras) {
        CHECK(near(glm::vec3(camera.camera_to_world[3]), glm::vec3(0.5f, 0.5f, 3.0f), kPrintedTolerance));
    }
}

TEST_CASE("MeshPrimitiveModes has all seven modes") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene s = load_ok(sample(*samples, "MeshPrimitiveModes"));
    std::set<scene::PrimitiveMode> modes;
    for (const scene::Mesh& mesh : s.meshes) {
        for (const scene::Primitive& primitive : mesh.primitives) modes.insert(primitive.mode);
    }
    CHECK(modes.size() == 7);
    CHECK(modes.count(scene::PrimitiveMode::Points) == 1);
    CHECK(modes.count(scene::PrimitiveMode::LineLoop) == 1);
    CHECK(modes.count(scene::PrimitiveMode::TriangleFan) == 1);
}

TEST_CASE("MultipleScenes: default scene 1, or the scene asked for") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene by_default = load_ok(sample(*samples, "MultipleScenes"));
    REQUIRE(by_default.instances.size() == 1);
    CHECK(by_default.instances[0].mesh == 1);

    scene::LoadOptions first;
    first.scene_index = 0;
    const scene::Scene scene0 = load_ok(sample(*samples, "MultipleScenes"), first);
    REQUIRE(scene0.instances.size() == 1);
    CHECK(scene0.instances[0].mesh == 0);
    CHECK(scene0.meshes.size() == 2); // every mesh is loaded; instances pick
}

TEST_CASE("SimpleSparseAccessor: sparse values replace the dense ones") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene s = load_ok(sample(*samples, "SimpleSparseAccessor"));
    const std::vector<glm::vec3>& positions = s.meshes[0].primitives[0].positions;
    REQUIRE(positions.size() == 14);
    CHECK(positions[7] == glm::vec3(0, 1, 0));   // untouched
    CHECK(positions[8] == glm::vec3(1, 2, 0));   // sparse index 8
    CHECK(positions[10] == glm::vec3(3, 3, 0));  // sparse index 10
    CHECK(positions[12] == glm::vec3(5, 4, 0));  // sparse index 12
    CHECK(positions[13] == glm::vec3(6, 1, 0));
    CHECK(s.world_bounds.max == glm::vec3(6, 4, 0));
}

TEST_CASE("TriangleWithoutIndices gets indices 0..n-1") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene s = load_ok(sample(*samples, "TriangleWithoutIndices"));
    CHECK(s.meshes[0].primitives[0].indices == std::vector<std::uint32_t>{0, 1, 2});
}

TEST_CASE("BoxVertexColors: COLOR_0 as RGBA with alpha 1") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene s = load_ok(sample(*samples, "BoxVertexColors"));
    const scene::Primitive& primitive = s.meshes[0].primitives[0];
    REQUIRE(primitive.colors.size() == 24);
    for (const glm::vec4& color : primitive.colors) CHECK(color.a == 1.0f);
}

TEST_CASE("Box: the parent node matrix becomes the instance's world transform") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene s = load_ok(sample(*samples, "Box"));
    REQUIRE(s.instances.size() == 1);
    const glm::mat4 rotation_x(glm::vec4(1, 0, 0, 0), glm::vec4(0, 0, -1, 0),
                               glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 0, 1));
    CHECK(near(s.instances[0].world, rotation_x, kMatrixTolerance));
    CHECK(near(s.world_bounds.min, glm::vec3(-0.5f), kPrintedTolerance));
    CHECK(near(s.world_bounds.max, glm::vec3(0.5f), kPrintedTolerance));
    REQUIRE(s.materials.size() == 1);
    CHECK(s.materials[0].base_color_factor.r == doctest::Approx(0.8));

    // The same box moved by the matrix's translation column: the bounds follow.
    scene_test::TempDir dir;
    scene_test::Json gltf = scene_test::read_json(sample(*samples, "Box"));
    gltf["nodes"][0]["matrix"][12] = 10.0;
    gltf["nodes"][0]["matrix"][14] = -2.0;
    const std::string moved = (dir.path() / "moved.gltf").string();
    scene_test::write_text(moved, gltf.dump());
    const scene::Scene m = load_ok(moved);
    CHECK(near(m.world_bounds.min, glm::vec3(9.5f, -0.5f, -2.5f), kPrintedTolerance));
    CHECK(near(m.world_bounds.max, glm::vec3(10.5f, 0.5f, -1.5f), kPrintedTolerance));
}

TEST_CASE("OrientationTest: TRS and matrix nodes") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene s = load_ok(sample(*samples, "OrientationTest"));
    // ArrowX1: translation (5,0,0), rotation quaternion about -X, scale ~1.
    const scene::Instance& trs = instance_named(s, "ArrowX1");
    const glm::quat q(0.9537169933319092f, -0.30070576071739197f, 0.0f, 0.0f);
    const glm::mat4 expected_trs = glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0)) *
                                   glm::mat4_cast(q) *
                                   glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.9999999403953552f, 0.9999999403953552f));
    CHECK(near(trs.world, expected_trs, kMatrixTolerance));
    // T * R * S, not another order: the translation column is untouched.
    CHECK(near(glm::vec3(trs.world[3]), glm::vec3(5, 0, 0), kPrintedTolerance));

    const scene::Instance& matrix = instance_named(s, "ArrowX2");
    const double m[16] = {1.0000000221841605, 0, 0, 0, 0, 0.9961947216654676, 0.08715572783347625, 0,
                          0, -0.08715572783347625, 0.9961947216654676, 0, -5.0, 0, 0, 1};
    CHECK(near(matrix.world, glm::mat4(glm::make_mat4(m)), kMatrixTolerance));

    const scene::Instance& z1 = instance_named(s, "ArrowZ1");
    CHECK(near(glm::vec3(z1.world[3]), glm::vec3(0, 0, 5), kPrintedTolerance));
    const scene::Instance& base = instance_named(s, "BaseCube");
    CHECK(near(base.world, glm::mat4(1.0f), kMatrixTolerance));
}

TEST_CASE("textured samples decode their images to RGBA8") {
    const auto samples = test_samples::corpus_folder("gltf-samples");
    if (!samples) return;
    const scene::Scene box = load_ok(sample(*samples, "BoxTextured"));
    scene_test::check_one_image(box, 256, 256);
    CHECK(box.materials[0].base_color_texture == 0);

    const scene::Scene uv = load_ok(sample(*samples, "TextureCoordinateTest"));
    CHECK(uv.images[0].width == 512);
    CHECK(uv.images[0].height == 512);
}

} // TEST_SUITE
