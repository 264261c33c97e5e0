// The panel's per-pass numbers on offscreen contexts: fragments (samples
// passed) from window::FragmentCounter on desktop GL (OSMesa), bounded
// below by the pixels the frame covers and above by the screen boxes of
// the triangles drawn; its one n/a line on OpenGL ES (EGL); and the
// recursion effect's levels as rows of their own, for the fragment
// counter and the GPU timer alike. Each test skips with the backend's
// error when its context cannot be made.
#include "rig.hpp"

#include <doctest/doctest.h>

#include <gl/offscreen_target.hpp>
#include <plan/mirror_geometry.hpp>
#include <plan/view_links.hpp>
#include <plan/view_tree.hpp>
#include <plan/world_geometry.hpp>
#include <render/pass_context.hpp>
#include <window/fragment_counter.hpp>
#include <window/gpu_timer.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using window_test::make_rig;
using window_test::Rig;

constexpr int kWidthPx = 128, kHeightPx = 72;

render::RenderOptions small_frame() {
    render::RenderOptions o;
    o.width_px = kWidthPx;
    o.height_px = kHeightPx;
    return o;
}

// The counter's rows of one frame of `effect` (single-sample, kWidthPx x
// kHeightPx), the GPU timer's rows of the same frame into `timed` when
// given, and the frame's image into `image` when given.
std::vector<window::FragmentCounter::PassSamples> count_frame(const Rig& rig, plan::Effect effect,
                                                              const render::RenderOptions& options,
                                                              std::vector<window::GpuTimer::PassTime>* timed = nullptr,
                                                              image::Image* image = nullptr) {
    window::FragmentCounter counter(*rig.context, *rig.fn);
    window::GpuTimer timer(*rig.context, *rig.fn);
    auto target = gl::OffscreenTarget::create(*rig.fn, {kWidthPx, kHeightPx});
    REQUIRE_MESSAGE(target.ok(), target.error());
    render::RenderOptions o = options;
    o.pass_end = [&](const char* pass) {
        timer.mark(pass);
        counter.mark(pass);
    };
    timer.begin();
    counter.begin();
    REQUIRE(rig.renderer->render_into(effect, render_test::showcase_cameras(kWidthPx, kHeightPx), o, *target).ok());
    counter.end();
    timer.end();
    rig.fn->Finish(); // every query answered: the next begin() reads them
    timer.begin();    // the timer's other query (its frames alternate)
    timer.end();
    timer.begin();
    counter.begin();
    std::vector<window::FragmentCounter::PassSamples> rows = counter.last_passes();
    counter.end();
    timer.end();
    if (timed) {
        *timed = timer.last_passes();
    }
    if (image) {
        auto drawn = target->read_rgba8();
        REQUIRE_MESSAGE(drawn.ok(), drawn.error());
        *image = std::move(*drawn);
    }
    CHECK(rig.fn->GetError() == GL_NO_ERROR);
    return rows;
}

// At least one sample passes the depth test in every pixel the frame covers
// (the first fragment there meets the cleared depth): the pixels that are
// not the clear colour.
std::uint64_t covered_pixels(const image::Image& picture) {
    const auto byte = [](float v) { return static_cast<std::uint8_t>(std::lround(v * 255.0f)); };
    const std::uint8_t sky[3] = {byte(render::kClearColor.r), byte(render::kClearColor.g), byte(render::kClearColor.b)};
    std::uint64_t covered = 0;
    for (std::size_t i = 0; i < picture.rgba.size(); i += 4) {
        covered += picture.rgba[i] != sky[0] || picture.rgba[i + 1] != sky[1] || picture.rgba[i + 2] != sky[2];
    }
    return covered;
}

// At most: each triangle passes at most once per sample it covers, and it
// covers no pixel outside its screen bounding box (clamped to the
// viewport; the whole viewport when a corner is not in front of the eye).
// Summed over the scene's triangles drawn with `pair` into a single-sample
// width x height viewport.
std::uint64_t triangle_box_bound(const scene::Scene& scene, const frustum::MatrixPair<float>& pair, int width_px,
                                 int height_px) {
    std::uint64_t bound = 0;
    for (const plan::WorldPrimitive& primitive : plan::WorldGeometry::from_scene(scene).primitives) {
        for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
            float x0 = static_cast<float>(width_px), y0 = static_cast<float>(height_px), x1 = 0.0f, y1 = 0.0f;
            bool behind = false;
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::vec4 clip = pair.matrix() * glm::vec4(primitive.vertices[primitive.indices[t + k]].position, 1.0f);
                behind = behind || clip.w <= 1e-6f;
                const float x = (clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(width_px);
                const float y = (clip.y / clip.w * 0.5f + 0.5f) * static_cast<float>(height_px);
                x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
            if (behind) {
                bound += static_cast<std::uint64_t>(width_px) * static_cast<std::uint64_t>(height_px);
                continue;
            }
            const auto span = [](float low, float high, int size) -> std::uint64_t {
                const float a = std::max(0.0f, std::floor(low)), b = std::min(static_cast<float>(size), std::ceil(high));
                return b > a ? static_cast<std::uint64_t>(b - a) : 0;
            };
            bound += span(x0, x1, width_px) * span(y0, y1, height_px);
        }
    }
    return bound;
}

std::vector<std::string> names(const std::vector<window::FragmentCounter::PassSamples>& rows) {
    std::vector<std::string> out;
    for (const auto& row : rows) {
        out.push_back(row.pass);
    }
    return out;
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("desktop GL: samples passed per pass, at least the covered pixels, at most the triangles' boxes") {
    const auto rig = make_rig(gl::Backend::OsMesa);
    if (!rig) {
        return;
    }
    window::FragmentCounter counter(*rig->context, *rig->fn);
    REQUIRE(counter.available());
    CHECK_FALSE(counter.unavailable_reason());
    const scene::Scene& scene = render_test::showcase();
    const plan::Cameras cameras = render_test::showcase_cameras(kWidthPx, kHeightPx);

    image::Image plain_image;
    const auto plain = count_frame(*rig, plan::Effect::Plain, small_frame(), nullptr, &plain_image);
    REQUIRE(names(plain) == std::vector<std::string>{"main view"});
    const std::uint64_t covered = covered_pixels(plain_image);
    const std::uint64_t boxes = triangle_box_bound(scene, cameras.main.pair, kWidthPx, kHeightPx);
    MESSAGE("plain main view: " << plain[0].samples << " samples, " << covered << " pixels covered, boxes bound "
                                << boxes << " (viewport " << kWidthPx * kHeightPx << " px)");
    CHECK(covered > 0);
    CHECK(plain[0].samples >= covered);
    CHECK(plain[0].samples <= boxes);

    const auto mirror = count_frame(*rig, plan::Effect::Mirror, small_frame());
    REQUIRE(names(mirror) == std::vector<std::string>{"reflection", "main view"});
    auto view = plan::plan_reflection(*scene.mirror, cameras.main.pair, kWidthPx, kHeightPx,
                                      plan::MirrorMethod::Oblique, scene.world_bounds);
    REQUIRE_MESSAGE(view.ok(), view.error());
    REQUIRE(view->has_value());
    const plan::ReflectionView& reflection = **view;
    const std::uint64_t reflected_boxes =
        triangle_box_bound(scene, reflection.pair, reflection.texture_width_px, reflection.texture_height_px);
    MESSAGE("mirror reflection: " << mirror[0].samples << " samples in a " << reflection.texture_width_px << "x"
                                  << reflection.texture_height_px << " texture, boxes bound " << reflected_boxes);
    CHECK(mirror[0].samples > 0);
    CHECK(mirror[0].samples <= reflected_boxes);
    CHECK(mirror[1].samples > 0);
}

TEST_CASE("OpenGL ES: no fragment counts, the panel's one n/a line, and no GL error from the counter") {
    const auto rig = make_rig(gl::Backend::Egl);
    if (!rig) {
        return;
    }
    window::FragmentCounter counter(*rig->context, *rig->fn);
    CHECK_FALSE(counter.available());
    REQUIRE(counter.unavailable_reason());
    CHECK(*counter.unavailable_reason() == "n/a: OpenGL ES occlusion queries are boolean (run with --context gl)");
    CHECK(count_frame(*rig, plan::Effect::Mirror, small_frame()).empty());
}

// The rows expected of the recursion effect, from the plan the renderer
// draws: "level k (n views)" for each level, deepest first, then "main view".
std::vector<std::string> planned_rows(plan::LinkSet set, int depth) {
    const scene::Scene& scene = render_test::showcase();
    const auto camera = render_test::showcase_cameras(kWidthPx, kHeightPx).main.pair;
    auto links = plan::place_facing_links(camera, scene.world_bounds, set);
    REQUIRE_MESSAGE(links.ok(), links.error());
    auto nodes = plan::plan_view_tree(camera, *links, {depth, kWidthPx, kHeightPx, plan::ViewBounds::Tight});
    REQUIRE_MESSAGE(nodes.ok(), nodes.error());
    std::vector<int> views;
    for (const plan::ViewNode& node : *nodes) {
        views.resize(std::max(views.size(), static_cast<std::size_t>(node.level) + 1), 0);
        ++views[static_cast<std::size_t>(node.level)];
    }
    std::vector<std::string> rows;
    for (std::size_t level = views.size(); level-- > 1;) {
        rows.push_back("level " + std::to_string(level) + " (" + std::to_string(views[level]) +
                       (views[level] == 1 ? " view)" : " views)"));
    }
    rows.push_back("main view");
    return rows;
}

TEST_CASE("recursion: one row per level, deepest first, with samples and GPU time of its own") {
    const auto rig = make_rig(gl::Backend::OsMesa);
    if (!rig) {
        return;
    }
    for (const plan::LinkSet set : {plan::LinkSet::Mirrors, plan::LinkSet::Portals}) {
        CAPTURE(plan::to_string(set));
        render::RenderOptions o = small_frame();
        o.recursion_links = set;
        o.recursion_depth = 3;
        const std::vector<std::string> expected = planned_rows(set, o.recursion_depth);
        CHECK(expected.size() == 4); // the showcase's camera sees three levels deep
        std::vector<window::GpuTimer::PassTime> timed;
        const auto rows = count_frame(*rig, plan::Effect::Recursion, o, &timed);
        CHECK(names(rows) == expected);
        for (const auto& row : rows) {
            CAPTURE(row.pass);
            CHECK(row.samples > 0);
        }
        if (timed.empty()) {
            MESSAGE("no timestamps in this context: GPU time rows not checked");
            continue;
        }
        REQUIRE(timed.size() == expected.size());
        for (std::size_t i = 0; i < timed.size(); ++i) {
            CHECK(timed[i].pass == expected[i]);
            CHECK(timed[i].gpu_ms > 0.0);
        }
    }
}

} // TEST_SUITE
