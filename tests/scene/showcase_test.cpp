// assets/showcase.gltf (made by scripts/make_showcase.py) loads and has the
// objects the demo relies on.
#include "../skips.hpp"
#include "helpers.hpp"

#include "scene/load_gltf.hpp"
#include "support/child_process.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <map>

namespace {

const scene::Camera* camera_named(const scene::Scene& s, const std::string& name) {
    for (const scene::Camera& camera : s.cameras) {
        if (camera.name == name) return &camera;
    }
    return nullptr;
}

} // namespace

TEST_SUITE("scene") {

TEST_CASE("showcase: contents, mirror, lens and cameras") {
    frustum::Result<scene::Scene> result = scene::load_gltf(scene_test::showcase_path());
    INFO(result.error());
    REQUIRE(result.ok());
    const scene::Scene& s = *result;

    std::map<std::string, int> instance_by_name;
    for (std::size_t i = 0; i < s.instances.size(); ++i) {
        instance_by_name[s.instances[i].node_name] = static_cast<int>(i);
    }
    for (const std::string name : {"floor", "mirror", "mirror_backing", "marker_behind_mirror", "box_blue",
                             "box_green", "pyramid_yellow", "cylinder_purple", "sphere_orange", "lens"}) {
        CAPTURE(name);
        CHECK(instance_by_name.count(name) == 1);
    }
    CHECK(s.instances.size() == 10);

    // Every mesh has normals; the floor has vertex colours.
    for (const scene::Mesh& mesh : s.meshes) {
        for (const scene::Primitive& primitive : mesh.primitives) {
            CAPTURE(mesh.name);
            CHECK(primitive.normals.size() == primitive.positions.size());
        }
    }
    const scene::Mesh& floor = s.meshes[s.instances[instance_by_name["floor"]].mesh];
    CHECK(floor.primitives[0].colors.size() == floor.primitives[0].positions.size());

    // Mirror: 3 x 2 m, standing 5 cm above the floor, reflecting toward +Z-ish.
    REQUIRE(s.mirror.has_value());
    const scene::MirrorRect& mirror = *s.mirror;
    CHECK(mirror.instance == instance_by_name["mirror"]);
    CHECK(glm::length(mirror.a1) == doctest::Approx(3.0).epsilon(1e-5));
    CHECK(glm::length(mirror.a2) == doctest::Approx(2.0).epsilon(1e-5));
    CHECK(mirror.corner.y == doctest::Approx(0.05).epsilon(1e-5));
    const glm::vec3 normal = glm::normalize(glm::cross(mirror.a1, mirror.a2));
    CHECK(normal.z > 0.9f);
    CHECK(normal.x > 0.1f); // turned slightly
    // The marker is behind the mirror plane, the coloured objects in front.
    const glm::vec3 centre = mirror.corner + 0.5f * (mirror.a1 + mirror.a2);
    auto side = [&](const std::string& name) {
        return glm::dot(glm::vec3(s.instances[instance_by_name[name]].world[3]) - centre, normal);
    };
    CHECK(side("marker_behind_mirror") < -0.5f);
    for (const std::string name : {"box_blue", "box_green", "pyramid_yellow", "cylinder_purple", "sphere_orange"}) {
        CAPTURE(name);
        CHECK(side(name) > 0.5f);
    }

    // Seen from "main": where the sight line to `p` crosses the mirror plane,
    // in the mirror's local quad coordinates ([-0.5, 0.5]^2 is on the mirror).
    REQUIRE(camera_named(s, "main") != nullptr);
    const glm::vec3 main_eye(camera_named(s, "main")->camera_to_world[3]);
    auto on_mirror = [&](const glm::vec3& p) {
        const glm::vec3 ray = p - main_eye;
        const float t = glm::dot(centre - main_eye, normal) / glm::dot(ray, normal);
        const glm::vec3 offset = main_eye + t * ray - centre;
        const glm::vec2 uv(glm::dot(offset, mirror.a1) / glm::dot(mirror.a1, mirror.a1),
                           glm::dot(offset, mirror.a2) / glm::dot(mirror.a2, mirror.a2));
        return t > 0.0f && std::abs(uv.x) < 0.5f && std::abs(uv.y) < 0.5f;
    };
    // The coloured objects show up in the reflection...
    for (const std::string name : {"box_blue", "box_green", "pyramid_yellow", "cylinder_purple", "sphere_orange"}) {
        CAPTURE(name);
        const glm::vec3 p(s.instances[instance_by_name[name]].world[3]);
        CHECK(on_mirror(p - 2.0f * glm::dot(p - centre, normal) * normal));
    }
    // ...and the marker is hidden behind the mirror: every vertex of it.
    const scene::Instance& marker = s.instances[instance_by_name["marker_behind_mirror"]];
    for (const glm::vec3& vertex : s.meshes[marker.mesh].primitives[0].positions) {
        CHECK(on_mirror(glm::vec3(marker.world * glm::vec4(vertex, 1.0f))));
    }

    REQUIRE(s.lens.has_value());
    CHECK(s.lens->instance == instance_by_name["lens"]);
    CHECK(s.lens->radius_m == doctest::Approx(0.4));
    CHECK(s.lens->center.z == doctest::Approx(3.6));

    REQUIRE(s.cameras.size() == 2);
    const scene::Camera* main_camera = camera_named(s, "main");
    const scene::Camera* overview = camera_named(s, "overview");
    REQUIRE(main_camera != nullptr);
    REQUIRE(overview != nullptr);
    CHECK(main_camera->znear_m == doctest::Approx(0.1));
    REQUIRE(main_camera->zfar_m.has_value());
    CHECK(*main_camera->zfar_m == doctest::Approx(100.0));
    REQUIRE(main_camera->aspect.has_value());
    CHECK(*main_camera->aspect == doctest::Approx(16.0 / 9.0).epsilon(1e-5));
    // "main" looks at the mirror's centre (down its local -Z).
    const glm::vec3 eye(main_camera->camera_to_world[3]);
    const glm::vec3 forward = -glm::vec3(main_camera->camera_to_world[2]);
    CHECK(glm::dot(forward, glm::normalize(centre - eye)) == doctest::Approx(1.0).epsilon(1e-4));
    CHECK(glm::dot(forward, normal) < -0.9f); // facing the reflecting side
    // "overview" is higher and wider.
    CHECK(overview->camera_to_world[3].y > main_camera->camera_to_world[3].y + 2.0f);
    CHECK(overview->yfov_rad > main_camera->yfov_rad);

    CHECK(s.world_bounds.min.y == doctest::Approx(0.0));
    CHECK(s.world_bounds.min.x == doctest::Approx(-5.0));
    CHECK(s.world_bounds.max.x == doctest::Approx(5.0));
}

TEST_CASE("showcase: the committed file is small and what the script generates") {
    const scene_test::Bytes committed = scene_test::read_bytes(scene_test::showcase_path());
    CHECK(committed.size() < 200u * 1024u);
    const std::string python = support::find_on_path("python3");
    if (python.empty()) {
        test_skips::skip("python3 not found: the showcase is not regenerated");
        return;
    }
    scene_test::TempDir dir;
    const std::string regenerated = (dir.path() / "showcase.gltf").string();
    support::Launch launch; // tests/support's runner: at most 120 s, then a failure naming the command
    launch.args = {FRUSTUM_SOURCE_DIR "/scripts/make_showcase.py", "--out", regenerated};
    const support::Outcome made = support::run(python, launch);
    REQUIRE_MESSAGE(made.exit_status == 0, made.err);
    // If this fails, run scripts/make_showcase.py and commit assets/showcase.gltf.
    CHECK(scene_test::read_bytes(regenerated) == committed);
}

} // TEST_SUITE
