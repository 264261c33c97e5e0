// Renderer::render_into (what the window draws with) and move_mirror on an
// offscreen context; skipped with the backend's error when there is none.
#include "rig.hpp"

#include <doctest/doctest.h>

#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <gl/offscreen_target.hpp>
#include <image/compare.hpp>
#include <render/renderer.hpp>
#include <window/gpu_timer.hpp>
#include <window/mirror_pose.hpp>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace {

using window_test::make_rig;
using window_test::Rig;

render::RenderOptions options() {
    render::RenderOptions o;
    o.width_px = 256;
    o.height_px = 144;
    o.msaa_samples = 1; // as the single-sample targets render_into() draws into here
    return o;
}

image::Image render_image(const Rig& rig, plan::Effect effect) {
    auto picture = rig.renderer->render(effect, render_test::showcase_cameras(), options());
    REQUIRE_MESSAGE(picture.ok(), picture.error());
    return std::move(*picture);
}

int pixels_over(const image::Image& a, const image::Image& b) {
    const auto diff = image::compare(a, b, 0);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    return diff->pixels_over;
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("render_into an existing target draws what render() returns") {
    const auto rig = make_rig();
    if (!rig) {
        return;
    }
    auto target = gl::OffscreenTarget::create(*rig->fn, {256, 144});
    REQUIRE_MESSAGE(target.ok(), target.error());
    for (plan::Effect effect : plan::kAllEffects) {
        CAPTURE(plan::to_string(effect));
        // Twice into the same target: nothing of the previous frame survives.
        for (int pass = 0; pass < 2; ++pass) {
            REQUIRE(rig->renderer->render_into(effect, render_test::showcase_cameras(), options(), *target).ok());
        }
        auto drawn = target->read_rgba8();
        REQUIRE_MESSAGE(drawn.ok(), drawn.error());
        CHECK(pixels_over(*drawn, render_image(*rig, effect)) == 0);
    }
}

TEST_CASE("move_mirror moves the reflection, and the identity puts it back exactly") {
    const auto rig = make_rig();
    if (!rig) {
        return;
    }
    const scene::Scene& scene = render_test::showcase();
    const image::Image before = render_image(*rig, plan::Effect::Mirror);
    window::MirrorPose pose;
    pose.turn_rad = 0.26f;
    pose.push_m = 0.3f;
    const std::vector<int> attached = window::mirror_attachments(scene);
    REQUIRE(rig->renderer->move_mirror(window::mirror_motion(*scene.mirror, pose), attached).ok());
    const image::Image moved = render_image(*rig, plan::Effect::Mirror);
    CHECK(pixels_over(before, moved) > 500);
    // The plain frame shows the moved surface and backing too.
    CHECK(pixels_over(render_image(*rig, plan::Effect::Plain), before) > 0);
    REQUIRE(rig->renderer->move_mirror(glm::mat4(1.0f), attached).ok());
    CHECK(pixels_over(before, render_image(*rig, plan::Effect::Mirror)) == 0);
}

TEST_CASE("move_mirror rejects a bad motion or instance") {
    const auto rig = make_rig();
    if (!rig) {
        return;
    }
    const auto scaled = rig->renderer->move_mirror(glm::mat4(2.0f), {});
    REQUIRE_FALSE(scaled.ok());
    CHECK(scaled.error().rfind("render::Renderer::move_mirror(): motion must be rigid", 0) == 0);
    const auto out_of_range = rig->renderer->move_mirror(glm::mat4(1.0f), {999});
    REQUIRE_FALSE(out_of_range.ok());
    CHECK(out_of_range.error().find("attached instance 999 is out of range") != std::string::npos);
}

// The window's per-pass GPU time: timestamp queries as each pass ends,
// read two frames later (the timer's double buffer). The frame they must fit
// in: the CPU wall time from before begin() to after glFinish(), which the
// GPU work between the stamps cannot exceed (tolerance 5% + 0.01 ms, two
// clocks). (The frame's own GL_TIME_ELAPSED reads back a clock value on
// Mesa's llvmpipe here, so it is not the bound.)
TEST_CASE("the GPU timer gives the mirror effect's reflection and main passes, positive, within the frame") {
    const auto rig = make_rig();
    if (!rig) {
        return;
    }
    window::GpuTimer timer(*rig->context, *rig->fn);
    if (!timer.available()) {
        test_skips::skip("the context has neither GL_EXT_disjoint_timer_query nor GL_ARB_timer_query");
        return;
    }
    auto target = gl::OffscreenTarget::create(*rig->fn, {256, 144});
    REQUIRE_MESSAGE(target.ok(), target.error());
    render::RenderOptions o = options();
    o.pass_end = [&timer](const char* pass) { timer.mark(pass); };
    const auto start = std::chrono::steady_clock::now();
    timer.begin();
    REQUIRE(rig->renderer->render_into(plan::Effect::Mirror, render_test::showcase_cameras(), o, *target).ok());
    timer.end();
    rig->fn->Finish();
    const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    timer.begin(); // a frame without passes in the other query
    timer.end();
    timer.begin(); // reads the mirror frame
    timer.end();
    const std::vector<window::GpuTimer::PassTime>& passes = timer.last_passes();
    if (passes.empty()) {
        test_skips::skip("the context's timestamp queries answer 0 (no GL_TIMESTAMP bits)");
        return;
    }
    REQUIRE(passes.size() == 2);
    CHECK(passes[0].pass == "reflection");
    CHECK(passes[1].pass == "main view");
    double sum_ms = 0.0;
    for (const auto& pass : passes) {
        CAPTURE(pass.pass);
        CHECK(pass.gpu_ms > 0.0);
        sum_ms += pass.gpu_ms;
    }
    MESSAGE("frame wall " << wall_ms << " ms, reflection " << passes[0].gpu_ms << " ms, main view "
                          << passes[1].gpu_ms << " ms");
    CHECK(sum_ms <= wall_ms * 1.05 + 0.01);
    // The frame's GPU time spans its passes and fits in its wall time (on
    // llvmpipe's offscreen context GL_TIME_ELAPSED answered a clock reading,
    // ~1.7e7 ms; the timer takes the frame from its stamps there).
    REQUIRE(timer.last_ms().has_value());
    MESSAGE("frame GPU " << *timer.last_ms() << " ms");
    CHECK(*timer.last_ms() >= sum_ms);
    CHECK(*timer.last_ms() <= wall_ms * 1.05 + 0.01);
}

} // TEST_SUITE
