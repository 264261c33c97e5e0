// Shared by the render_*_test.cpp files: the showcase scene, a renderer on
// some backend, mirror-pixel masks, masked comparison, and saving the
// images of a failed comparison next to the test binary.
#pragma once

#include "gl_test_support.hpp"
#include "../plan/showcase.hpp"

#include <doctest/doctest.h>

#include <image/compare.hpp>
#include <image/image.hpp>
#include <frustum/reflect.hpp>
#include <gl/offscreen_target.hpp>
#include <image/png.hpp>
#include <plan/mirror_geometry.hpp>
#include <plan/mirror_placement.hpp>
#include <plan/scene_fit.hpp>
#include <render/scene_pass.hpp>
#include <plan/camera.hpp>
#include <render/renderer.hpp>
#include <scene/load_gltf.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace render_test {

inline render::RenderOptions options(int width_px = kWidthPx, int height_px = kHeightPx) {
    render::RenderOptions o;
    o.width_px = width_px;
    o.height_px = height_px;
    o.mirror_tint = glm::vec3(1.0f); // a perfect mirror: reflection pixels compare 1:1
    o.msaa_samples = 1;              // exact pixel comparisons (render_msaa_test.cpp turns it on)
    return o;
}

// A context, its table and a renderer of `scene`. Members die in reverse
// order: the renderer (and its GL objects) before the context.
struct RenderEnvironment {
    std::unique_ptr<gl_test::Environment> env;
    std::optional<render::Renderer> renderer;

    image::Image render(plan::Effect effect, const plan::Cameras& cameras, const render::RenderOptions& o) const {
        auto picture = renderer->render(effect, cameras, o);
        REQUIRE_MESSAGE(picture.ok(), picture.error());
        return std::move(*picture);
    }
};

// Null (after a MESSAGE) when `backend` cannot make a context.
inline std::unique_ptr<RenderEnvironment> renderer_on(std::unique_ptr<gl_test::Environment> env,
                                                      const scene::Scene& scene) {
    auto out = std::make_unique<RenderEnvironment>();
    out->env = std::move(env);
    auto renderer = render::Renderer::create(*out->env->context, out->env->fn, scene);
    REQUIRE_MESSAGE(renderer.ok(), renderer.error());
    out->renderer.emplace(std::move(*renderer));
    return out;
}

// Null (after recording a skip) when the backend cannot make a context.
inline std::unique_ptr<RenderEnvironment> make_renderer(gl::Backend backend, const scene::Scene& scene = showcase()) {
    auto env = gl_test::make_environment(backend);
    return env ? renderer_on(std::move(env), scene) : nullptr;
}

// EGL, else OSMesa; null (after recording a skip with both errors) when neither works.
inline std::unique_ptr<RenderEnvironment> make_any_renderer(const scene::Scene& scene = showcase()) {
    auto env = gl_test::make_any_environment();
    return env ? renderer_on(std::move(env), scene) : nullptr;
}

// `auto name = make_any_renderer();`, the test case ending there (its skip
// recorded) when neither EGL nor OSMesa works.
#define RENDER_TEST_ANY_RENDERER(name)                   \
    auto name = render_test::make_any_renderer();        \
    if (!name)                                           \
    return

// What frustum-demo render derives for a scene it has never seen: a mirror
// placed for the default camera when the scene has none (added to `scene`), the default camera, a
// renderer on `env`, and options() at the given size with the curved
// mirror's sagitta fitted to the mirror (docs/any-scene.md).
struct DerivedScene {
    plan::Cameras cameras;
    std::optional<render::Renderer> renderer;
    render::RenderOptions options;
};
inline DerivedScene derive_scene(const gl_test::Environment& env, scene::Scene& scene, int width_px, int height_px) {
    const auto index = plan::find_camera(scene, std::nullopt);
    REQUIRE_MESSAGE(index.ok(), index.error());
    auto cameras = plan::make_cameras(scene, *index, width_px, height_px);
    REQUIRE_MESSAGE(cameras.ok(), cameras.error());
    plan::place_mirror(scene, plan::MirrorRequest{}, &cameras->main.pair); // where this camera sees it
    REQUIRE(scene.mirror);
    auto renderer = render::Renderer::create(*env.context, env.fn, scene);
    REQUIRE_MESSAGE(renderer.ok(), renderer.error());
    DerivedScene out{std::move(*cameras), std::move(*renderer), options(width_px, height_px)};
    out.options.curved.sagitta_m = plan::fit_sagitta_m(*scene.mirror, out.options.curved.shape, scene.world_bounds);
    return out;
}

// <test binary's folder>/render_test_output (the build tree), created on demand.
inline std::filesystem::path output_dir() {
    std::error_code error;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
    const auto dir = (error ? std::filesystem::current_path() : exe.parent_path()) / "render_test_output";
    std::filesystem::create_directories(dir, error);
    return dir;
}

// Saves a, b and their amplified difference as <stem>-a.png, -b.png, -diff.png.
inline void save_failure(const std::string& stem, const image::Image& a, const image::Image& b) {
    const auto dir = output_dir();
    const auto diff = image::diff_image(a, b);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    for (const auto& [suffix, picture] : {std::pair<const char*, const image::Image*>{"-a.png", &a},
                                         {"-b.png", &b}, {"-diff.png", &*diff}}) {
        const auto status = image::write_png(*picture, (dir / (stem + suffix)).string());
        CHECK_MESSAGE(status.ok(), status.error());
    }
    MESSAGE("saved " << stem << "-{a,b,diff}.png in " << dir.string());
}

// Pixels of one image, selected by a mask (true = compared).
using Mask = std::vector<bool>;

inline int count(const Mask& mask) { return static_cast<int>(std::count(mask.begin(), mask.end(), true)); }

// The pixels whose centres the mirror quad covers: its four corners
// projected by the camera pair's matrix and the quad rasterized here on the
// CPU (rows from the top, as read back), not drawn by the code under test.
// The corners must lie in front of the eye.
inline Mask projected_mirror_mask(const frustum::MatrixPair<float>& camera, const scene::MirrorRect& mirror,
                                  int width_px, int height_px) {
    const glm::vec3 corners[4] = {mirror.corner, mirror.corner + mirror.a1, mirror.corner + mirror.a1 + mirror.a2,
                                  mirror.corner + mirror.a2};
    glm::dvec2 window[4]; // pixels from the bottom-left
    for (int i = 0; i < 4; ++i) {
        const glm::dvec4 clip = glm::dmat4(camera.matrix()) * glm::dvec4(glm::dvec3(corners[i]), 1.0);
        REQUIRE(clip.w > 0.0);
        window[i] = glm::dvec2((clip.x / clip.w + 1.0) / 2.0 * width_px, (clip.y / clip.w + 1.0) / 2.0 * height_px);
    }
    Mask mask(static_cast<std::size_t>(width_px * height_px), false);
    for (int row = 0; row < height_px; ++row) {
        for (int x = 0; x < width_px; ++x) {
            const glm::dvec2 c(x + 0.5, height_px - row - 0.5);
            int positive = 0, negative = 0;
            for (int i = 0; i < 4; ++i) {
                const glm::dvec2 e = window[(i + 1) % 4] - window[i], d = c - window[i];
                const double side = e.x * d.y - e.y * d.x;
                positive += side > 0.0;
                negative += side < 0.0;
            }
            mask[static_cast<std::size_t>(row * width_px + x)] = positive == 4 || negative == 4;
        }
    }
    return mask;
}

// The visible mirror pixels: the mirror quad's projection
// (projected_mirror_mask) less what stands in front of the mirror, found as
// the pixels that the composite with tint 0 does not paint black (nothing
// else in the showcase is pure black: ambient light). Only occlusion comes
// from the effect; that its black pixels lie inside the projection is
// checked (render_mirror_test.cpp, "the mirror's pixels are its quad's projection").
inline Mask effect_black_pixels(const RenderEnvironment& r, const plan::Cameras& cameras, render::RenderOptions o) {
    o.mirror_tint = glm::vec3(0.0f);
    const image::Image black = r.render(plan::Effect::Mirror, cameras, o);
    Mask mask(static_cast<std::size_t>(black.width * black.height));
    for (int y = 0; y < black.height; ++y) {
        for (int x = 0; x < black.width; ++x) {
            const image::Rgba p = image::pixel_at(black, x, y);
            mask[static_cast<std::size_t>(y * black.width + x)] = p[0] == 0 && p[1] == 0 && p[2] == 0;
        }
    }
    return mask;
}

inline Mask both(const Mask& a, const Mask& b) {
    Mask out(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] && b[i];
    return out;
}

inline Mask mirror_mask(const RenderEnvironment& r, const plan::Cameras& cameras, render::RenderOptions o) {
    REQUIRE(r.renderer.has_value());
    const scene::MirrorRect& mirror = *showcase().mirror;
    return both(projected_mirror_mask(cameras.main.pair, mirror, o.width_px, o.height_px),
                effect_black_pixels(r, cameras, o));
}

struct MaskedDiff {
    int compared = 0;    // pixels in the mask
    int pixels_over = 0; // of them, with some RGB channel differing by more than the tolerance
    int max_abs = 0;     // largest channel difference in the mask
    double mean_abs = 0; // mean |a - b| over the RGB channels of the mask's pixels
};

inline MaskedDiff compare_masked(const image::Image& a, const image::Image& b, const Mask& mask, int tolerance) {
    const auto d = image::compare_masked(a, b, mask, image::Channels::Rgb, tolerance);
    REQUIRE_MESSAGE(d.ok(), d.error());
    return MaskedDiff{d->pixel_count, d->pixels_over, d->max_abs, d->mean_abs};
}

// The marker's lit red: red high, green and blue near zero (no other
// showcase colour comes close: orange has g >= 0.5, purple b >= 0.75).
inline bool is_marker_red(const image::Rgba& p) { return p[0] >= 100 && p[1] <= 40 && p[2] <= 40; }

// Pixels of the mask more than 2 LSB away from the clear colour.
inline int count_not_sky(const image::Image& picture, const Mask& mask) {
    const image::Rgba sky{static_cast<std::uint8_t>(render::kClearColor.r * 255.0f + 0.5f),
                          static_cast<std::uint8_t>(render::kClearColor.g * 255.0f + 0.5f),
                          static_cast<std::uint8_t>(render::kClearColor.b * 255.0f + 0.5f), 255};
    int not_sky = 0;
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            not_sky += mask[static_cast<std::size_t>(y * picture.width + x)] &&
                       !gl_test::near(image::pixel_at(picture, x, y), sky, 2);
        }
    }
    return not_sky;
}

inline int count_red(const image::Image& picture, const Mask& mask) {
    int red = 0;
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            red += mask[static_cast<std::size_t>(y * picture.width + x)] && is_marker_red(image::pixel_at(picture, x, y));
        }
    }
    return red;
}

// The mirror effect's reference: the scene geometry itself reflected in the
// mirror plane (frustum::reflection_matrix as a model matrix, so the winding
// flips per draw), drawn from the unchanged camera into a new target (left
// bound), with fragments in front of the mirror plane discarded (they are
// reflections of what lies behind it).
inline gl::OffscreenTarget draw_mirrored_geometry(const RenderEnvironment& r, const plan::Cameras& cameras,
                                                  const render::DepthPolicy& depth) {
    const gl::Functions& fn = r.env->fn;
    auto target = gl::OffscreenTarget::create(fn, {kWidthPx, kHeightPx});
    REQUIRE_MESSAGE(target.ok(), target.error());
    const render::PassContext ctx = r.renderer->pass_context(depth, render::Lighting{});
    const scene::MirrorRect& mirror = *showcase().mirror;
    const frustum::Plane<float> plane = plan::mirror_plane(mirror);
    render::begin_frame(ctx);
    render::SceneDraw draw(cameras.main.pair);
    draw.pre_model = frustum::reflection_matrix(plane);
    draw.clip_plane = plane.flipped(); // keep what lies behind the mirror after reflection
    draw.skip_instance = mirror.instance;
    render::draw_scene(ctx, draw);
    return std::move(*target);
}

inline render::DepthPolicy apply_depth_policy(const RenderEnvironment& r,
                                              render::DepthPath path = render::DepthPath::ClipControlWhenAvailable) {
    auto depth = render::DepthPolicy::apply(r.env->fn, *r.env->context, path);
    REQUIRE_MESSAGE(depth.ok(), depth.error());
    return *depth;
}

inline image::Image render_mirrored_geometry(const RenderEnvironment& r, const plan::Cameras& cameras) {
    const gl::OffscreenTarget target = draw_mirrored_geometry(r, cameras, apply_depth_policy(r));
    auto picture = target.read_rgba8();
    REQUIRE_MESSAGE(picture.ok(), picture.error());
    return std::move(*picture);
}

} // namespace render_test
