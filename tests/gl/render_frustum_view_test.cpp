// The frustum view (README: the main camera's frustum, yellow, drawn from its
// key points, seen by the overview camera): its side edges pass through the
// main frustum's corners. The corners are computed here from the pair's
// inverse (M^-1 times the clip cube's corners, §3.2 eq. 8 by definition),
// not with key_points() or frustum_lines(), and projected with the overview
// pair; points along each side edge must have a yellow pixel within 1.5 px.
#include "render_test_support.hpp"

#include <frustum/depth_range.hpp>

#include <cmath>

namespace {

bool is_main_frustum_yellow(const image::Rgba& p) { // (1, 0.85, 0.1): (255, 217, 26)
    return p[0] >= 215 && p[1] >= 177 && p[1] <= 250 && p[2] <= 80;
}

// Yellow within `radius_px` of the pixel position (x from the left, y from the bottom).
bool yellow_near(const image::Image& picture, glm::vec2 at_px, float radius_px) {
    const int r = static_cast<int>(std::ceil(radius_px));
    for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
            const int x = static_cast<int>(std::floor(at_px.x)) + dx, y_up = static_cast<int>(std::floor(at_px.y)) + dy;
            if (x < 0 || y_up < 0 || x >= picture.width || y_up >= picture.height) continue;
            if (glm::length(glm::vec2(x + 0.5f, y_up + 0.5f) - at_px) > radius_px + 0.71f) continue;
            if (is_main_frustum_yellow(image::pixel_at(picture, x, picture.height - 1 - y_up))) return true;
        }
    }
    return false;
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("the frustum view's yellow edges pass through the main frustum's corners as the overview sees them") {
    RENDER_TEST_ANY_RENDERER(r);
    const auto cameras = render_test::showcase_cameras();
    const auto o = render_test::options();
    const image::Image picture = r->render(plan::Effect::Frustum, cameras, o);
    const glm::mat4 inverse = cameras.main.pair.inverse();
    const glm::mat4 overview = cameras.overview.pair.matrix();
    const float z_near = frustum::clip_z_near<float>(cameras.main.pair.depth());
    const float z_far = frustum::clip_z_far<float>(cameras.main.pair.depth());
    const glm::vec2 corners[4] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    int sampled = 0, on_line = 0, off_line = 0;
    for (const glm::vec2& c : corners) {
        const glm::vec4 near_h = inverse * glm::vec4(c, z_near, 1.0f), far_h = inverse * glm::vec4(c, z_far, 1.0f);
        const glm::vec3 near_point = glm::vec3(near_h) / near_h.w;
        // Towards the far corner (or along the edge's direction when it is at infinity).
        const glm::vec3 direction =
            far_h.w > 0.0f ? glm::vec3(far_h) / far_h.w - near_point : glm::normalize(glm::vec3(far_h));
        const float length_m = far_h.w > 0.0f ? 1.0f : 50.0f;
        for (int i = 1; i <= 40; ++i) {
            const glm::vec3 p = near_point + (length_m * static_cast<float>(i) / 40.0f) * direction;
            const glm::vec4 clip = overview * glm::vec4(p, 1.0f);
            if (!(clip.w > 0.0f)) continue;
            const glm::vec2 ndc = glm::vec2(clip) / clip.w;
            const glm::vec2 at_px = (ndc * 0.5f + 0.5f) * glm::vec2(o.width_px, o.height_px);
            if (at_px.x < 3 || at_px.y < 3 || at_px.x > o.width_px - 3 || at_px.y > o.height_px - 3) continue;
            ++sampled;
            on_line += yellow_near(picture, at_px, 1.5f) ? 1 : 0;
            // Control: 6 px to the side of the edge there is no yellow (unless another edge is near).
            const glm::vec4 next = overview * glm::vec4(p + 0.01f * length_m * direction, 1.0f);
            const glm::vec2 along = glm::normalize(glm::vec2(next) / next.w - ndc);
            off_line += yellow_near(picture, at_px + 6.0f * glm::vec2(-along.y, along.x), 1.0f) ? 1 : 0;
        }
    }
    MESSAGE("frustum view: " << on_line << " of " << sampled << " points on the main frustum's side edges are yellow, "
                             << off_line << " points 6 px beside them");
    CHECK(sampled >= 40);
    // Measured at 256x144: 53 of 60 on the edges (the magenta reflection
    // frustum, drawn after, covers the rest), 0 of 60 beside them. Bounds:
    // 80% on the edges, at most 15% beside them (where edges meet).
    CHECK(on_line * 10 >= sampled * 8);
    CHECK(off_line * 100 <= sampled * 15);
    if (on_line * 10 < sampled * 8) {
        render_test::save_failure("frustum-view", picture, picture);
    }
}

} // TEST_SUITE
