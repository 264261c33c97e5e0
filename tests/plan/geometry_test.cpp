// The render library's math, without a GL context: the mirror's reflection
// camera and the frustum line sets.
#include "showcase.hpp"

#include <frustum/projection.hpp>
#include <frustum/queries.hpp>
#include <plan/frustum_lines.hpp>
#include <plan/mirror_geometry.hpp>

namespace {

glm::vec2 to_pixels(const frustum::MatrixPair<float>& pair, const glm::vec3& p, glm::vec2 size_px) {
    const glm::vec4 clip = pair.matrix() * glm::vec4(p, 1.0f);
    return (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * size_px;
}

frustum::MatrixPair<float> looking(const glm::vec3& eye, const glm::vec3& target) {
    auto view = frustum::look_at<float>(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    auto projection = frustum::perspective<float>(0.8f, 16.0f / 9.0f, 0.1f, 100.0f, frustum::DepthRange::ZeroToOne);
    REQUIRE(view.ok());
    REQUIRE(projection.ok());
    return frustum::compose(*projection, *view);
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("cameras are found by name, node name or index, and placed by their node") {
    const scene::Scene& s = render_test::showcase();
    CHECK(*plan::find_camera(s, std::nullopt) == 0); // "main"
    CHECK(*plan::find_camera(s, std::string("overview")) == 1);
    CHECK(*plan::find_camera(s, std::string("1")) == 1);
    const auto missing = plan::find_camera(s, std::string("2"));
    REQUIRE_FALSE(missing.ok());
    CHECK(missing.error() == "plan::find_camera(): no camera '2'; the scene's cameras are: main, overview");
    // The view is the closed-form inverse of camera_to_world: the eye read
    // back from the pair (§3.2, O = m2') is the camera node's translation.
    const auto eye = frustum::eye_point(render_test::showcase_cameras().main.pair);
    REQUIRE(eye.has_value());
    CHECK(glm::distance(*eye, glm::vec3(0.8f, 1.7f, 6.5f)) < 1e-4f);
}

TEST_CASE("a reflection texel is the screen pixel it lies under") {
    const scene::MirrorRect& mirror = *render_test::showcase().mirror;
    const auto camera = render_test::showcase_cameras().main.pair;
    const glm::vec2 screen(render_test::kWidthPx, render_test::kHeightPx);
    for (auto method : {plan::MirrorMethod::Oblique, plan::MirrorMethod::ReflectOnly}) {
        INFO("method " << plan::to_string(method));
        const auto plan = plan::plan_reflection(mirror, camera, render_test::kWidthPx, render_test::kHeightPx,
                                                method, render_test::showcase().world_bounds);
        REQUIRE_MESSAGE(plan.ok(), plan.error());
        REQUIRE(plan->has_value());
        const plan::ReflectionView& view = **plan;
        CHECK(view.pair.flips_winding());
        CHECK(view.texture_width_px == view.screen_rect.width);
        CHECK(view.texture_height_px == view.screen_rect.height);
        const glm::vec2 texture(view.texture_width_px, view.texture_height_px);
        const glm::vec2 origin(view.screen_rect.x, view.screen_rect.y);
        // R (eq. 16) fixes the mirror plane, so on it the cropped reflection
        // pair is the camera followed by the crop: within 1/1000 pixel.
        for (float s : {0.1f, 0.5f, 0.9f}) {
            for (float t : {0.1f, 0.5f, 0.9f}) {
                const glm::vec3 on_mirror = mirror.corner + s * mirror.a1 + t * mirror.a2;
                const glm::vec2 screen_px = to_pixels(camera, on_mirror, screen);
                const glm::vec2 texel_px = origin + to_pixels(view.pair, on_mirror, texture);
                CHECK(glm::distance(screen_px, texel_px) < 1e-3f);
            }
        }
    }
}

TEST_CASE("no reflection when the mirror is seen from behind or out of view") {
    const scene::MirrorRect& mirror = *render_test::showcase().mirror;
    const glm::vec3 center = mirror.corner + 0.5f * (mirror.a1 + mirror.a2);
    const glm::vec3 normal = glm::normalize(glm::cross(mirror.a1, mirror.a2));
    const auto plan_from = [&](const frustum::MatrixPair<float>& camera) {
        auto plan = plan::plan_reflection(mirror, camera, 64, 36, plan::MirrorMethod::Oblique,
                                          render_test::showcase().world_bounds);
        REQUIRE_MESSAGE(plan.ok(), plan.error());
        return plan->has_value();
    };
    CHECK(plan_from(looking(center + 4.0f * normal, center)));
    CHECK_FALSE(plan_from(looking(center - 4.0f * normal, center)));             // behind
    CHECK_FALSE(plan_from(looking(center + 4.0f * normal, center + 8.0f * normal))); // facing away
}

TEST_CASE("pixels seen of a polygon: rounded out, clipped before projecting, empty when unseen") {
    // Eye at the origin looking down -z, 160 x 90 pixels, near 0.1 m.
    const auto camera = looking(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::vec2 size(160.0f, 90.0f);
    // In front: the box of the projected corners, floor / ceil.
    const std::vector<glm::vec3> ahead = {{-0.3f, -0.2f, -2.0f}, {0.25f, -0.2f, -2.0f}, {0.0f, 0.35f, -3.0f}};
    glm::vec2 low(1e9f), high(-1e9f);
    for (const glm::vec3& p : ahead) {
        low = glm::min(low, to_pixels(camera, p, size));
        high = glm::max(high, to_pixels(camera, p, size));
    }
    const auto seen = plan::pixels_seen(camera, ahead, 160, 90);
    REQUIRE(seen.has_value());
    CHECK(seen->x == static_cast<int>(std::floor(low.x)));
    CHECK(seen->y == static_cast<int>(std::floor(low.y)));
    CHECK(seen->x + seen->width == static_cast<int>(std::ceil(high.x)));
    CHECK(seen->y + seen->height == static_cast<int>(std::ceil(high.y)));
    // A triangle reaching behind the eye: the corner behind (w < 0) would
    // project to the opposite side if it were divided; clipped first, the
    // rectangle is what is in front, here the right half of the screen and
    // below the middle row (the triangle lies at y = -0.5 m, x >= 0).
    const std::vector<glm::vec3> crossing = {{0.0f, -0.5f, -3.0f}, {2.0f, -0.5f, -3.0f}, {2.0f, -0.5f, 3.0f}};
    const auto behind = plan::pixels_seen(camera, crossing, 160, 90);
    REQUIRE(behind.has_value());
    CHECK(behind->x >= 79);
    CHECK(behind->y + behind->height <= 45);
    CHECK(behind->width > 0);
    // Wholly behind the eye, or outside the view: nothing.
    CHECK_FALSE(plan::pixels_seen(camera, {{0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 2.0f}}, 160, 90));
    CHECK_FALSE(plan::pixels_seen(camera, {{50.0f, 0.0f, -1.0f}, {51.0f, 0.0f, -1.0f}, {50.0f, 1.0f, -1.0f}}, 160, 90));
    // What screen_rect() refuses is not seen either.
    CHECK_FALSE(plan::pixels_seen(camera, {{0.0f, 0.0f, -1.0f}, {1.0f, 0.0f, -1.0f}}, 160, 90));
}

TEST_CASE("frustum lines: edges, eye lines and crosses where the key points are finite") {
    const plan::FrustumLineStyle style{0.1f, 50.0f};
    auto perspective = frustum::perspective<float>(1.0f, 1.5f, 0.5f, 20.0f, frustum::DepthRange::ZeroToOne);
    auto infinite = frustum::perspective<float>(1.0f, 1.5f, 0.5f, frustum::infinite_far, frustum::DepthRange::ZeroToOne);
    auto orthographic = frustum::orthographic<float>(-2.0f, 2.0f, -1.0f, 1.0f, 0.0f, 10.0f, frustum::DepthRange::ZeroToOne);
    REQUIRE(perspective.ok());
    REQUIRE(infinite.ok());
    REQUIRE(orthographic.ok());
    // 12 edges, 4 eye lines, crosses (3 segments) at O and D; O1, O2 at infinity.
    CHECK(plan::frustum_lines(*perspective, style).size() == 2 * (12 + 4 + 3 + 3));
    // The eye of an orthographic frustum is at infinity: no eye lines or cross.
    CHECK(plan::frustum_lines(*orthographic, style).size() == 2 * (12 + 3));
    // Infinite far: each side edge is a ray infinite_length_m long, going on
    // from its near corner away from the eye (the origin).
    const auto lines = plan::frustum_lines(*infinite, style);
    REQUIRE(lines.size() == 2 * (12 + 4 + 3 + 3));
    for (std::size_t edge = 0; edge < 4; ++edge) {
        const std::size_t side = 6 * edge + 4; // near, far, side per corner
        CHECK(glm::distance(lines[side], lines[side + 1]) == doctest::Approx(style.infinite_length_m).epsilon(1e-4));
        const glm::vec3 from_eye = glm::normalize(lines[side]);
        CHECK(glm::dot(glm::normalize(lines[side + 1] - lines[side]), from_eye) == doctest::Approx(1.0f).epsilon(1e-5));
    }
}

} // TEST_SUITE
