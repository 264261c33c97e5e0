// The orbit camera: it starts where the scene's camera is, and its pair is
// look_at + perspective, so with the scene camera's own lens and no roll the
// first orbit pair reproduces that camera.
#include "../plan/showcase.hpp"

#include <doctest/doctest.h>
// Approx epsilon of these float results: 2 float ulps relative (2 x 1.19e-7), doctest's
// default (1.19e-5) being 100; each passes at 2 ulps (measured: tightened until one failed).
static constexpr double kFloatTwoUlps = 2.4e-7;

#include <window/orbit_camera.hpp>

#include <frustum/projection.hpp>
#include <frustum/queries.hpp>

#include <cmath>

namespace {

float max_abs_difference(const glm::mat4& a, const glm::mat4& b) {
    float worst = 0.0f;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            worst = std::max(worst, std::abs(a[c][r] - b[c][r]));
        }
    }
    return worst;
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("orbit_from_pair starts at the camera's eye, looking its way") {
    const plan::Cameras cameras = render_test::showcase_cameras();
    const window::OrbitCamera orbit = window::orbit_from_pair(cameras.main.pair, render_test::showcase().world_bounds);
    // assets/README.md: main stands at (0.8, 1.7, 6.5) and looks at the mirror's centre (0, 1.05, -2).
    const glm::vec3 eye = orbit.eye();
    CHECK(eye.x == doctest::Approx(0.8f).epsilon(1e-4));
    CHECK(eye.y == doctest::Approx(1.7f).epsilon(1e-4));
    CHECK(eye.z == doctest::Approx(6.5f).epsilon(1e-4));
    const glm::vec3 expected = glm::normalize(glm::vec3(0.0f, 1.05f, -2.0f) - glm::vec3(0.8f, 1.7f, 6.5f));
    CHECK(glm::dot(orbit.forward(), expected) == doctest::Approx(1.0f).epsilon(1e-5));
    CHECK(orbit.distance_m > 0.0f);
}

TEST_CASE("the first orbit pair reproduces the scene camera (no roll, same lens)") {
    const scene::Scene& scene = render_test::showcase();
    const plan::Cameras cameras = render_test::showcase_cameras();
    const window::OrbitCamera orbit = window::orbit_from_pair(cameras.main.pair, scene.world_bounds);
    const window::OrbitProjection projection = window::orbit_projection(scene, *plan::find_camera(render_test::showcase(), std::nullopt));
    CHECK(projection.yfov_rad == doctest::Approx(50.0 * 3.14159265358979 / 180.0).epsilon(1e-5));
    REQUIRE(projection.near_m);
    CHECK(*projection.near_m == doctest::Approx(0.1f).epsilon(kFloatTwoUlps));
    const auto pair = window::orbit_pair(orbit, projection, 256.0f / 144.0f, scene.world_bounds);
    REQUIRE_MESSAGE(pair.ok(), pair.error());
    // Entries reach ~1e1; float round-off of two constructions.
    CHECK(max_abs_difference(pair->matrix(), cameras.main.pair.matrix()) < 2e-4f);
    CHECK(max_abs_difference(pair->inverse(), cameras.main.pair.inverse()) < 2e-3f);
}

TEST_CASE("orbit, pan and zoom move the eye as documented") {
    window::OrbitCamera camera;
    camera.target = glm::vec3(1.0f, 2.0f, 3.0f);
    camera.distance_m = 4.0f;
    const glm::vec3 start = camera.eye();
    CHECK(start.z == doctest::Approx(7.0f).epsilon(kFloatTwoUlps)); // yaw 0, pitch 0: on the +Z side

    window::orbit(camera, 1.5707963f, 0.0f); // a quarter turn about +Y
    CHECK(camera.eye().x == doctest::Approx(5.0f).epsilon(kFloatTwoUlps));
    CHECK(glm::length(camera.eye() - camera.target) == doctest::Approx(4.0f).epsilon(kFloatTwoUlps));

    window::orbit(camera, 0.0f, 10.0f); // pitch is clamped short of the pole
    CHECK(camera.pitch_rad == doctest::Approx(window::kMaxPitchRad).epsilon(kFloatTwoUlps));
    window::orbit(camera, 0.0f, -20.0f);
    CHECK(camera.pitch_rad == doctest::Approx(-window::kMaxPitchRad).epsilon(kFloatTwoUlps));
    const auto steep = window::orbit_pair(camera, {}, 1.0f, scene::Bounds{});
    CHECK_MESSAGE(steep.ok(), steep.error());

    camera.pitch_rad = 0.0f;
    const glm::vec3 before = camera.eye();
    window::pan(camera, 0.5f, 0.25f);
    CHECK(glm::length(camera.eye() - before) == doctest::Approx(std::sqrt(0.5f * 0.5f + 0.25f * 0.25f)).epsilon(kFloatTwoUlps));
    CHECK(camera.eye().y - before.y == doctest::Approx(0.25f).epsilon(kFloatTwoUlps));

    window::zoom(camera, 0.5f, 1.0f, 10.0f);
    CHECK(camera.distance_m == doctest::Approx(2.0f).epsilon(kFloatTwoUlps));
    window::zoom(camera, 0.01f, 1.0f, 10.0f);
    CHECK(camera.distance_m == doctest::Approx(1.0f).epsilon(kFloatTwoUlps));
    window::zoom(camera, 100.0f, 1.0f, 10.0f);
    CHECK(camera.distance_m == doctest::Approx(10.0f).epsilon(kFloatTwoUlps));
}

TEST_CASE("without a perspective scene camera the orbit fits its depth range to the scene") {
    scene::Bounds bounds{glm::vec3(-1.0f), glm::vec3(1.0f)};
    window::OrbitCamera camera;
    camera.distance_m = 10.0f;
    const window::OrbitProjection fitted = window::orbit_projection(render_test::showcase(), -1);
    CHECK_FALSE(fitted.near_m);
    const auto pair = window::orbit_pair(camera, fitted, 1.5f, bounds);
    REQUIRE_MESSAGE(pair.ok(), pair.error());
    // The whole bounding sphere (radius sqrt 3) lies between near and far.
    const auto planes = frustum::planes(*pair);
    for (const glm::vec3 corner : {glm::vec3(-1.0f), glm::vec3(1.0f), glm::vec3(1.0f, -1.0f, 1.0f)}) {
        CHECK(planes.near.distance(corner) > 0.0f);
        REQUIRE(planes.far);
        CHECK(planes.far->distance(corner) > 0.0f);
    }
}

TEST_CASE("orbit_pair reports the frustum library's error") {
    window::OrbitCamera camera;
    window::OrbitProjection projection;
    projection.near_m = -1.0f;
    const auto pair = window::orbit_pair(camera, projection, 1.0f, scene::Bounds{});
    REQUIRE_FALSE(pair.ok());
    CHECK(pair.error().rfind("window::orbit_pair(): frustum::perspective(): ", 0) == 0);
}

} // TEST_SUITE
