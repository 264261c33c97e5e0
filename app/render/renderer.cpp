#include "render/renderer.hpp"

#include "render/frustum_view_pass.hpp"
#include "render/mirror_pass.hpp"
#include "render/scene_pass.hpp"
#include "render/tile_pass.hpp"

#include <gl/errors.hpp>
#include <gl/offscreen_target.hpp>

#include <utility>
#include <vector>

namespace render {
namespace {

constexpr glm::vec4 kMainFrustumColor{1.0f, 0.85f, 0.1f, 1.0f};      // yellow
constexpr glm::vec4 kReflectionFrustumColor{0.9f, 0.1f, 0.9f, 1.0f}; // magenta

// Line sizes in proportion to the scene: crosses 2% of its diagonal,
// edges towards infinity twice the diagonal.
FrustumLineStyle line_style(const scene::Bounds& bounds) {
    const float diagonal_m = glm::length(bounds.max - bounds.min);
    const float size_m = diagonal_m > 0.0f ? diagonal_m : 1.0f;
    return {0.02f * size_m, 2.0f * size_m};
}

} // namespace

Renderer::Renderer(const gl::Context& context, const gl::Functions& fn, GpuScene gpu_scene, Programs programs,
                   const scene::Scene& scene)
    : context_(&context), fn_(&fn), gpu_scene_(std::move(gpu_scene)), programs_(std::move(programs)),
      mirror_(scene.mirror), bounds_(scene.world_bounds) {}

frustum::Result<Renderer> Renderer::create(const gl::Context& context, const gl::Functions& fn,
                                           const scene::Scene& scene) {
    auto programs = Programs::build(fn);
    if (!programs) {
        return frustum::Error{programs.error()};
    }
    auto gpu_scene = GpuScene::upload(fn, scene);
    if (!gpu_scene) {
        return frustum::Error{gpu_scene.error()};
    }
    return Renderer(context, fn, std::move(*gpu_scene), std::move(*programs), scene);
}

frustum::DepthRange Renderer::gpu_depth_range(DepthPath path) const {
    return DepthPolicy::choose(*fn_, *context_, path);
}

PassContext Renderer::pass_context(const DepthPolicy& depth, const Lighting& lighting) const {
    return PassContext{*fn_, context_->api(), programs_, gpu_scene_, depth, lighting};
}

frustum::Result<image::Image> Renderer::render(Effect effect, const Cameras& cameras,
                                               const RenderOptions& options) const {
    auto depth = DepthPolicy::apply(*fn_, *context_, options.depth);
    if (!depth) {
        return frustum::Error{depth.error()};
    }
    auto frame = gl::OffscreenTarget::create(*fn_, {options.width_px, options.height_px});
    if (!frame) {
        return frustum::Error{"render::Renderer::render(): " + frame.error()};
    }
    const PassContext ctx = pass_context(*depth, options.lighting);
    if (auto status = draw(effect, ctx, *frame, cameras, options); !status) {
        return frustum::Error{status.error()};
    }
    if (auto status = gl::check_error(*fn_, "render::Renderer::render()"); !status) {
        return frustum::Error{status.error()};
    }
    return frame->read_rgba8();
}

frustum::Status Renderer::draw(Effect effect, const PassContext& ctx, const gl::OffscreenTarget& frame,
                               const Cameras& cameras, const RenderOptions& options) const {
    switch (effect) {
    case Effect::Mirror:
        if (mirror_) {
            return draw_mirror_frame(
                ctx, frame, MirrorDraw{cameras.main.pair, *mirror_, options.mirror_method, options.mirror_tint, bounds_});
        }
        [[fallthrough]]; // no mirror: the plain frame
    case Effect::Plain:
        begin_frame(ctx);
        draw_scene(ctx, SceneDraw{cameras.main.pair});
        return {};
    case Effect::Tiles:
        return draw_tiled_frame(ctx, frame, cameras.main.pair, options.tile_columns, options.tile_rows);
    case Effect::Frustum: {
        std::vector<FrustumOverlay> overlays{{cameras.main.pair, kMainFrustumColor}};
        if (mirror_) {
            auto reflection = plan_reflection(*mirror_, cameras.main.pair, frame.width(), frame.height(),
                                              options.mirror_method, bounds_);
            if (!reflection) {
                return frustum::Error{reflection.error()};
            }
            if (*reflection) {
                overlays.push_back({(*reflection)->pair, kReflectionFrustumColor});
            }
        }
        return draw_frustum_view(ctx, cameras.overview.pair, overlays, line_style(bounds_));
    }
    }
    return {};
}

} // namespace render
