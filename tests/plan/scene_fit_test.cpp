// The derived defaults of the lens and non-affine effects (plan/scene_fit:
// fit_lens, fit_non_affine) and the explicit --lens-center, --lens-radius,
// --slit, --pivot, --mirror-plane and --mirror-rect, against what docs/any-scene.md says they are, worked
// out here with GLM's own camera (not the library's near-plane frame).
#include "showcase.hpp"

#include <doctest/doctest.h>

#include <frustum/projection.hpp>
#include <plan/mirror_placement.hpp>
#include <plan/scene_fit.hpp>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/glm.hpp>

#include <array>
#include <cmath>

namespace {

// fovy 60 degrees, aspect 2, near 0.5 m, far 50 m, from (0, 0, 5) to the origin.
constexpr float kFovyRad = 1.04719755f, kAspect = 2.0f, kNearM = 0.5f, kFarM = 50.0f;
const glm::vec3 kEye(0.0f, 0.0f, 5.0f);

frustum::MatrixPair<float> camera() {
    auto projection = frustum::perspective<float>(kFovyRad, kAspect, kNearM, kFarM, frustum::DepthRange::ZeroToOne);
    auto view = frustum::look_at<float>(kEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    REQUIRE(projection.ok());
    REQUIRE(view.ok());
    return frustum::compose(*projection, *view);
}

// The near plane's half extents and where GLM's camera puts p on it, in metres from its centre.
const float kHalfHeightM = kNearM * std::tan(kFovyRad / 2), kHalfWidthM = kAspect * kHalfHeightM;
glm::vec2 seen_on_near_plane(const glm::vec3& p) {
    const glm::mat4 m = glm::perspectiveRH_ZO(kFovyRad, kAspect, kNearM, kFarM) *
                        glm::lookAtRH(kEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::vec4 clip = m * glm::vec4(p, 1.0f);
    return glm::vec2(clip) / clip.w * glm::vec2(kHalfWidthM, kHalfHeightM);
}

// A unit box centred at (0.6, 0.3, 0): 5 m in front of the eye.
const scene::Bounds kBounds{{0.1f, -0.2f, -0.5f}, {1.1f, 0.8f, 0.5f}};
const glm::vec3 kMiddle(0.6f, 0.3f, 0.0f);

} // namespace

TEST_SUITE("plan") {

TEST_CASE("fit_lens: the derived lens is centred on the model as seen, half its radius as seen") {
    const auto lens = plan::fit_lens(camera(), std::nullopt, kBounds, {}, 2.0f);
    REQUIRE_MESSAGE(lens.ok(), lens.error());
    const glm::vec2 expected = seen_on_near_plane(kMiddle); // (0.6, 0.3) 5 m out: inside the middle 60%
    CHECK(std::abs(lens->center_m.x - expected.x) <= 1e-6f);
    CHECK(std::abs(lens->center_m.y - expected.y) <= 1e-6f);
    CHECK(std::abs(lens->center_m.x) > 0.01f); // not the frame's centre
    // Radius: half of the bounds' radius (sqrt(3) / 2 m) scaled to the near
    // plane at the model's depth (5 m): 0.0433 m, 0.15 of the half height.
    const float expected_radius_m = 0.5f * (0.5f * std::sqrt(3.0f)) * kNearM / 5.0f;
    CHECK(std::abs(lens->radius_m - expected_radius_m) <= 1e-5f);
    CHECK(lens->power == 2.0f);
}

TEST_CASE("fit_lens: a lens spot in front of the camera is used as it is seen") {
    const scene::LensSpot spot{glm::vec3(-0.5f, 0.2f, 1.0f), 0.3f, -1};
    const auto lens = plan::fit_lens(camera(), spot, kBounds, {}, 1.5f);
    REQUIRE_MESSAGE(lens.ok(), lens.error());
    const glm::vec2 expected = seen_on_near_plane(spot.center);
    CHECK(std::abs(lens->center_m.x - expected.x) <= 1e-6f);
    CHECK(std::abs(lens->center_m.y - expected.y) <= 1e-6f);
    CHECK(std::abs(lens->radius_m - 0.3f * kNearM / 4.0f) <= 1e-5f); // 4 m in front of the eye
}

TEST_CASE("fit_lens: --lens-center and --lens-radius are fractions of the frame's half extents") {
    plan::EffectFit fit;
    fit.lens_center = glm::vec2(0.5f, -0.25f);
    fit.lens_radius = 0.3f;
    const scene::LensSpot spot{glm::vec3(-0.5f, 0.2f, 1.0f), 0.3f, -1}; // given values win over the spot
    const auto lens = plan::fit_lens(camera(), spot, kBounds, fit, 2.0f);
    REQUIRE_MESSAGE(lens.ok(), lens.error());
    CHECK(std::abs(lens->center_m.x - 0.5f * kHalfWidthM) <= 1e-6f);
    CHECK(std::abs(lens->center_m.y + 0.25f * kHalfHeightM) <= 1e-6f);
    CHECK(std::abs(lens->radius_m - 0.3f * kHalfHeightM) <= 1e-6f);
}

TEST_CASE("fit_non_affine: pivot at the model centre's depth, slit a third of it, unless given") {
    const auto derived = plan::fit_non_affine(camera(), kBounds, plan::NonAffineOptions{}, {});
    REQUIRE_MESSAGE(derived.ok(), derived.error());
    CHECK(std::abs(derived->pivot_depth_m - 5.0f) <= 1e-5f);
    CHECK(std::abs(derived->slit_depth_m - 5.0f / 3.0f) <= 1e-5f);
    plan::EffectFit fit;
    fit.slit_m = 1.0f;
    fit.pivot_m = 4.0f;
    const auto given = plan::fit_non_affine(camera(), kBounds, plan::NonAffineOptions{}, fit);
    REQUIRE_MESSAGE(given.ok(), given.error());
    CHECK(given->slit_depth_m == 1.0f);
    CHECK(given->pivot_depth_m == 4.0f);
}

} // TEST_SUITE

// --mirror-plane and --mirror-rect (plan::place_mirror): the mirror the
// options say, on the showcase, whatever its own mirror node.
TEST_SUITE("plan") {

TEST_CASE("--mirror-plane puts the mirror in that plane, reflecting towards (a, b, c); --mirror-rect is the rectangle given") {
    {
        scene::Scene s = render_test::showcase();
        plan::MirrorRequest request;
        request.plane = glm::vec4(0.0f, 2.0f, 0.0f, 1.0f); // y = -0.5, unnormalized
        const auto said = plan::place_mirror(s, request);
        REQUIRE(s.mirror.has_value());
        CHECK(said.has_value()); // stderr says where it went
        const scene::MirrorRect& m = *s.mirror;
        for (const glm::vec3& p : {m.corner, m.corner + m.a1, m.corner + m.a2, m.corner + m.a1 + m.a2}) {
            CHECK(std::abs(p.y + 0.5f) <= 1e-5f);
        }
        const glm::vec3 n = glm::normalize(glm::cross(m.a1, m.a2));
        CHECK(n.y >= 1.0f - 1e-6f); // reflects towards +y
        // Under the model's centre (README: a square of the model's diagonal under its centre).
        const glm::vec3 centre = m.corner + 0.5f * (m.a1 + m.a2);
        const glm::vec3 middle = 0.5f * (s.world_bounds.min + s.world_bounds.max);
        CHECK(std::abs(centre.x - middle.x) <= 1e-4f);
        CHECK(std::abs(centre.z - middle.z) <= 1e-4f);
        CHECK(std::abs(glm::length(m.a1) - glm::length(m.a2)) <= 1e-4f);
    }
    {
        scene::Scene s = render_test::showcase();
        plan::MirrorRequest request;
        request.rect = std::array<float, 9>{1.0f, 2.0f, -3.0f, 2.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f};
        plan::place_mirror(s, request);
        REQUIRE(s.mirror.has_value());
        const scene::MirrorRect& m = *s.mirror;
        const glm::vec3 centre = m.corner + 0.5f * (m.a1 + m.a2);
        CHECK(std::abs(centre.x - 1.0f) + std::abs(centre.y - 2.0f) + std::abs(centre.z + 3.0f) <= 1e-5f);
        CHECK(std::abs(glm::length(m.a1) - 2.0f) <= 1e-5f);
        CHECK(std::abs(glm::length(m.a2) - 1.0f) <= 1e-5f);
        CHECK(glm::normalize(glm::cross(m.a1, m.a2)).z >= 1.0f - 1e-6f); // a x b = +z
    }
}

} // TEST_SUITE
