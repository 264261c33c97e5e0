// The same picture whatever the backend (EGL GLES 3.2 / OSMesa GL 4.5 core)
// and whatever the clip-space depth range ([0, 1] by clip control, or the
// pairs converted to [-1, 1]).
#include "render_test_support.hpp"

#include <array>

namespace {

constexpr plan::Effect kCompared[] = {plan::Effect::Plain, plan::Effect::Mirror, plan::Effect::Frustum};

void compare_images(const std::string& stem, const image::Image& a, const image::Image& b, int tolerance) {
    const auto diff = image::compare(a, b, tolerance);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    MESSAGE(stem << ": mean " << diff->mean_abs << ", max " << diff->max_abs << ", " << diff->pixels_over
                 << " pixels over " << tolerance);
    CHECK(diff->pixels_over == 0);
    if (diff->pixels_over != 0) {
        render_test::save_failure(stem, a, b);
    }
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("EGL and OSMesa render the same images") {
    const auto cameras = render_test::showcase_cameras();
    std::array<std::vector<image::Image>, 2> pictures;
    for (std::size_t b = 0; b < 2; ++b) {
        auto r = render_test::make_renderer(gl_test::kBackends[b]);
        if (!r) {
            return;
        }
        for (plan::Effect effect : kCompared) {
            pictures[b].push_back(r->render(effect, cameras, render_test::options()));
        }
    }
    // Both are llvmpipe: tolerance 1 LSB per channel (rounding), no pixel
    // beyond it. Measured: identical.
    for (std::size_t i = 0; i < std::size(kCompared); ++i) {
        compare_images(std::string("egl-vs-osmesa-") + std::string(plan::to_string(kCompared[i])), pictures[0][i],
                       pictures[1][i], 1);
    }
}

TEST_CASE("[0, 1] depth with clip control equals the [-1, 1] conversion") {
    const auto cameras = render_test::showcase_cameras();
    for (gl::Backend backend : gl_test::kBackends) {
        INFO("backend " << gl::to_string(backend));
        auto r = render_test::make_renderer(backend);
        if (!r) {
            continue;
        }
        if (r->renderer->gpu_depth_range(render::DepthPath::ClipControlWhenAvailable) != frustum::DepthRange::ZeroToOne) {
            if (gl_test::clip_control_removed_on_purpose()) { // then both paths are the [-1, 1] one
                CHECK(r->renderer->gpu_depth_range(render::DepthPath::ClipControlWhenAvailable) ==
                      frustum::DepthRange::MinusOneToOne);
            } else {
                test_skips::skip(std::string(gl::to_string(backend)) + ": no clip control, both paths are [-1, 1]");
            }
            continue;
        }
        auto o = render_test::options();
        for (plan::Effect effect : kCompared) {
            o.depth = render::DepthPath::ClipControlWhenAvailable;
            const image::Image zero_to_one = r->render(effect, cameras, o);
            o.depth = render::DepthPath::MinusOneToOne;
            const image::Image minus_one_to_one = r->render(effect, cameras, o);
            // x, y and w are the same rows in both; only depth values (and so
            // near-ties in the depth test) can differ. Tolerance 1 LSB, no
            // pixel beyond it. Measured: identical.
            compare_images(std::string("depth-") + std::string(gl::to_string(backend)) + "-" +
                               std::string(plan::to_string(effect)),
                           zero_to_one, minus_one_to_one, 1);
        }
    }
}

} // TEST_SUITE
