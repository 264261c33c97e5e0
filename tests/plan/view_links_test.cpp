// The recursion effect's facing mirrors (plan::place_facing_links) seen
// from the default camera of every scene the "any scene" tests walk: both
// mirrors inside the view, each covering a good part of it, whatever the
// camera's pitch (the framing camera of a sample looks down on the model).
#include "../sample_files.hpp"

#include <doctest/doctest.h>

#include <frustum/lens.hpp>
#include <plan/camera.hpp>
#include <plan/mirror_geometry.hpp>
#include <plan/view_links.hpp>
#include <scene/load_gltf.hpp>

#include <algorithm>
#include <optional>
#include <vector>

namespace {

constexpr int kW = 256, kH = 144;

// The part of a link's quad nearer to the eye than `depth_m` along the
// view direction `forward` (cut across its x axis), as a scene::MirrorRect
// for plan::mirror_screen_rect(); the whole quad when all of it is nearer.
scene::MirrorRect near_part(const plan::ViewLink& link, const glm::vec3& eye, const glm::vec3& forward,
                            float depth_m) {
    const frustum::Frame<float>& f = link.entry;
    // depth(t) = dot(origin + t x - eye, forward) for t in [-w, w] along x.
    const float w = link.half_width_m, at = glm::dot(f.origin - eye, forward), slope = glm::dot(f.x, forward);
    float low = -w, high = w;
    if (slope > 0.0f) {
        high = std::min(high, (depth_m - at) / slope);
    } else if (slope < 0.0f) {
        low = std::max(low, (depth_m - at) / slope);
    }
    scene::MirrorRect rect;
    rect.corner = f.origin + low * f.x - link.half_height_m * f.y;
    rect.a1 = std::max(high - low, 0.0f) * f.x;
    rect.a2 = 2.0f * link.half_height_m * f.y;
    return rect;
}

} // namespace

TEST_SUITE("plan") {

TEST_CASE("both facing mirrors lie inside the default camera's view of every sample") {
    for (const auto& file : test_samples::scene_files()) {
        CAPTURE(file.filename().string());
        auto loaded = scene::load_gltf(file.string());
        REQUIRE_MESSAGE(loaded.ok(), loaded.error());
        const auto index = plan::find_camera(*loaded, std::nullopt);
        REQUIRE_MESSAGE(index.ok(), index.error());
        auto cameras = plan::make_cameras(*loaded, *index, kW, kH);
        REQUIRE_MESSAGE(cameras.ok(), cameras.error());
        auto links = plan::place_facing_links(cameras->main.pair, loaded->world_bounds, plan::LinkSet::Mirrors);
        if (!links) {
            // Only a camera without an eye (orthographic) has no placement.
            CHECK(cameras->main.pair.matrix()[3][3] != 0.0f);
            continue;
        }
        REQUIRE(links->size() == 2);
        // Only the part in front of the model's centre counts: behind it
        // the model, or a floor under it, may hide the mirror.
        const auto near = frustum::near_plane_frame(cameras->main.pair);
        REQUIRE(near.ok());
        const glm::vec3 forward = glm::normalize(glm::cross(near->y_axis, near->x_axis));
        const glm::vec3 center = 0.5f * (loaded->world_bounds.min + loaded->world_bounds.max);
        const float depth_m = glm::dot(center - near->eye, forward);
        std::vector<plan::PixelRect> rects;
        for (const plan::ViewLink& link : *links) {
            const auto rect =
                plan::mirror_screen_rect(near_part(link, near->eye, forward, depth_m), cameras->main.pair, kW, kH);
            REQUIRE(rect);
            INFO("rectangle " << rect->width << "x" << rect->height << " at " << rect->x << "," << rect->y);
            // Seen along the corridor, each covers its side of the view: a
            // fifth of the width or more and over half of the height.
            CHECK(rect->width >= kW / 5);
            CHECK(rect->height >= kH / 2);
            rects.push_back(*rect);
        }
        // The left one left of the view's centre, the right one right of it.
        CHECK(rects[0].x + rects[0].width <= kW / 2);
        CHECK(rects[1].x >= kW / 2);
    }
}

} // TEST_SUITE
