#include "render/renderer.hpp"

#include "render/curved_pass.hpp"
#include "render/frustum_view_pass.hpp"
#include "render/lens_pass.hpp"
#include "plan/mirror_motion.hpp"
#include "render/mirror_pass.hpp"
#include "render/recursion_pass.hpp"
#include "render/scene_pass.hpp"
#include "render/tile_pass.hpp"

#include <gl/errors.hpp>
#include <gl/offscreen_target.hpp>

#include <string>
#include <utility>
#include <vector>

namespace render {
namespace {

constexpr glm::vec4 kMainFrustumColor{1.0f, 0.85f, 0.1f, 1.0f};      // yellow
constexpr glm::vec4 kReflectionFrustumColor{0.9f, 0.1f, 0.9f, 1.0f}; // magenta

// Line sizes in proportion to the scene: crosses 2% of its diagonal,
// edges towards infinity twice the diagonal.
plan::FrustumLineStyle line_style(const scene::Bounds& bounds) {
    const float diagonal_m = glm::length(bounds.max - bounds.min);
    const float size_m = diagonal_m > 0.0f ? diagonal_m : 1.0f;
    return {0.02f * size_m, 2.0f * size_m};
}

} // namespace

Renderer::Renderer(const gl::Context& context, const gl::Functions& fn, GpuScene gpu_scene, Programs programs,
                   FogPass fog_pass, const scene::Scene& scene, std::vector<LinkGroup> link_groups)
    : context_(&context), fn_(&fn), gpu_scene_(std::move(gpu_scene)), programs_(std::move(programs)),
      fog_pass_(std::move(fog_pass)),
      mirror_(scene.mirror), bounds_(scene.world_bounds), boxes_(plan::instance_boxes(scene)),
      scene_mirror_(scene.mirror),
      lens_(scene.lens),
      link_groups_(std::move(link_groups)), nonaffine_geometry_(plan::WorldGeometry::in_object_space(scene)) {
    for (const scene::Instance& instance : scene.instances) {
        scene_worlds_.push_back(instance.world);
    }
}

frustum::Result<Renderer> Renderer::create(const gl::Context& context, const gl::Functions& fn,
                                           const scene::Scene& scene) {
    auto programs = Programs::build(fn);
    if (!programs) {
        return programs.take_error();
    }
    auto fog_pass = FogPass::build(fn);
    if (!fog_pass) {
        return frustum::Error{fog_pass.error()};
    }
    auto gpu_scene = GpuScene::upload(fn, scene);
    if (!gpu_scene) {
        return gpu_scene.take_error();
    }
    // The quads of the portal pair, the facing mirrors and the facing
    // portal; link_group() places them for each frame's camera.
    std::vector<LinkGroup> groups;
    for (int mirrors : {0, 2, 0}) {
        std::vector<plan::ViewLink> links(static_cast<std::size_t>(mirrors ? mirrors : 1));
        for (plan::ViewLink& link : links) {
            link.kind = mirrors ? plan::ViewLink::Kind::Mirror : plan::ViewLink::Kind::Portal;
        }
        auto quads = GpuScene::upload(fn, plan::link_scene(links));
        if (!quads) {
            return frustum::Error{quads.error()};
        }
        groups.push_back(LinkGroup{std::move(links), std::move(*quads)});
    }
    return Renderer(context, fn, std::move(*gpu_scene), std::move(*programs), std::move(*fog_pass), scene,
                    std::move(groups));
}

frustum::Result<const Renderer::LinkGroup*> Renderer::link_group(plan::Effect effect, const RenderOptions& options,
                                                                 const frustum::MatrixPair<float>& camera) const {
    const plan::LinkSet set = options.recursion_links;
    const bool portal = effect == plan::Effect::Portal;
    LinkGroup& group = link_groups_[portal ? 0 : set == plan::LinkSet::Mirrors ? 1 : 2];
    auto placed = portal ? plan::place_portal_pair(camera, bounds_, boxes_) : plan::place_facing_links(camera, bounds_, set, boxes_);
    if (!placed) {
        return frustum::Error{placed.error()};
    }
    if (!portal) {
        plan::move_links(*placed, options.link_moves);
    }
    for (std::size_t i = 0; i < placed->size(); ++i) {
        plan::ViewLink& link = (*placed)[i];
        link.surface_instance = group.links[i].surface_instance;
        link.exit_instance = group.links[i].exit_instance;
        link.frame_instance = group.links[i].frame_instance;
        group.quads.set_instance_world(static_cast<std::size_t>(link.surface_instance), plan::link_world(link, false));
        if (link.exit_instance >= 0) {
            group.quads.set_instance_world(static_cast<std::size_t>(link.exit_instance), plan::link_world(link, true));
        }
        if (link.frame_instance >= 0) {
            group.quads.set_instance_world(static_cast<std::size_t>(link.frame_instance),
                                           plan::entry_frame_world(link));
        }
    }
    group.links = std::move(*placed);
    return &group;
}

frustum::DepthRange Renderer::gpu_depth_range(DepthPath path) const {
    return DepthPolicy::choose(*fn_, *context_, path);
}

PassContext Renderer::pass_context(const DepthPolicy& depth, const Lighting& lighting) const {
    return PassContext{*fn_, context_->api(), programs_, gpu_scene_, depth, lighting};
}

frustum::Result<image::Image> Renderer::render(plan::Effect effect, const plan::Cameras& cameras,
                                               const RenderOptions& options) const {
    auto samples = gl::choose_samples(*fn_, options.msaa_samples);
    if (!samples) {
        return samples.take_error_in("render::Renderer::render()");
    }
    auto frame = gl::OffscreenTarget::create(
        *fn_, {options.width_px, options.height_px, gl::ColorStorage::Renderbuffer, gl::DepthFormat::Depth24, *samples});
    if (!frame) {
        return frame.take_error_in("render::Renderer::render()");
    }
    if (auto status = render_into(effect, cameras, options, *frame); !status) {
        return status.take_error();
    }
    return frame->read_rgba8();
}

frustum::Status Renderer::render_into(plan::Effect effect, const plan::Cameras& cameras, const RenderOptions& options,
                                      const gl::OffscreenTarget& frame) const {
    return render_into(effect, cameras, options, frame, whole_frame(frame.width(), frame.height()));
}

frustum::Status Renderer::render_into(plan::Effect effect, const plan::Cameras& cameras, const RenderOptions& options,
                                      const gl::OffscreenTarget& frame, const FrameWindow& window,
                                      FrameCache* cache) const {
    if (window.rect.width != frame.width() || window.rect.height != frame.height() || window.rect.x < 0 ||
        window.rect.y < 0 || window.rect.x + window.rect.width > window.full_width_px ||
        window.rect.y + window.rect.height > window.full_height_px) {
        return frustum::Error{"render::Renderer::render_into(): window " + std::to_string(window.rect.width) + "x" +
                              std::to_string(window.rect.height) + "+" + std::to_string(window.rect.x) + "+" +
                              std::to_string(window.rect.y) + " must lie inside the " +
                              std::to_string(window.full_width_px) + "x" + std::to_string(window.full_height_px) +
                              " frame and match the " + std::to_string(frame.width()) + "x" +
                              std::to_string(frame.height()) + " target"};
    }
    auto depth = DepthPolicy::apply(*fn_, *context_, options.depth);
    if (!depth) {
        return depth.take_error();
    }
    frame.bind();
    PassContext ctx = pass_context(*depth, options.lighting);
    ctx.samples = frame.samples();
    ctx.pass_end = options.pass_end;
    ctx.window = window;
    ctx.frame_cache = cache;
    if (auto status = draw(effect, ctx, frame, cameras, options); !status) {
        return status;
    }
    if (ctx.pass_end) {
        ctx.pass_end("main view");
    }
    frame.bind();
    return gl::check_error(*fn_, "render::Renderer::render()");
}

frustum::Status Renderer::move_mirror(const glm::mat4& motion, const std::vector<int>& attached) {
    constexpr const char* kWhere = "render::Renderer::move_mirror()";
    if (!scene_mirror_) {
        return frustum::Error{std::string(kWhere) + ": the scene has no mirror"};
    }
    if (auto rigid = plan::check_rigid_motion(motion, kWhere); !rigid) {
        return rigid;
    }
    std::vector<int> moving = attached;
    if (scene_mirror_->instance >= 0) {
        moving.push_back(scene_mirror_->instance);
    }
    for (int index : moving) {
        if (index < 0 || static_cast<std::size_t>(index) >= scene_worlds_.size()) {
            return frustum::Error{std::string(kWhere) + ": attached instance " + std::to_string(index) +
                                  " is out of range (the scene has " + std::to_string(scene_worlds_.size()) +
                                  " instances)"};
        }
    }
    for (int index : moved_instances_) {
        gpu_scene_.set_instance_world(static_cast<std::size_t>(index), scene_worlds_[static_cast<std::size_t>(index)]);
    }
    for (int index : moving) {
        const auto i = static_cast<std::size_t>(index);
        gpu_scene_.set_instance_world(i, motion * scene_worlds_[i]);
    }
    moved_instances_ = std::move(moving);
    mirror_ = plan::moved_mirror(*scene_mirror_, motion);
    return {};
}

frustum::Status Renderer::draw(plan::Effect effect, const PassContext& ctx, const gl::OffscreenTarget& frame,
                               const plan::Cameras& given, const RenderOptions& options) const {
    // An orthographic main camera has no eye: the effects built from one
    // draw with its perspective twin (camera.hpp).
    const plan::Cameras cameras = plan::cameras_for(effect, given);
    std::optional<FogDraw> fog; // the plain and mirror effects draw it; the others leave it out
    if (options.fog) {
        fog = FogDraw{&fog_pass_, fit_fog(*options.fog, bounds_, ctx.clear_color),
                      options.fog->decode_reflection_unclipped};
    }
    // Every effect is planned for the whole frame; what reaches the target
    // is the crop of that plan to the window (frame_window.hpp).
    const FrameWindow window = window_of(ctx, frame.width(), frame.height());
    auto on_frame = crop_to_window(cameras.main.pair, window);
    if (!on_frame) {
        return on_frame.take_error_in("render::Renderer::render_into()");
    }
    switch (effect) {
    case plan::Effect::Lens:
        return draw_lens(ctx, frame, cameras.main.pair, options);
    case plan::Effect::NonAffine:
        return draw_non_affine(ctx, frame, cameras.main.pair, options);
    case plan::Effect::Curved:
        if (mirror_) {
            return draw_curved_mirror_frame(
                ctx, frame, CurvedDraw{cameras.main.pair, *mirror_, options.curved, options.mirror_tint, bounds_});
        }
        begin_frame(ctx); // no mirror: the plain frame
        draw_scene(ctx, SceneDraw{*on_frame});
        return {};
    case plan::Effect::Mirror:
        if (mirror_) {
            return draw_mirror_frame(ctx, frame,
                                     MirrorDraw{cameras.main.pair, *mirror_, options.mirror_method,
                                                options.mirror_tint, bounds_, fog});
        }
        [[fallthrough]]; // no mirror: the plain frame
    case plan::Effect::Plain:
        begin_frame(ctx);
        draw_scene(ctx, SceneDraw{*on_frame});
        return fog ? fog_pass_.apply(ctx, frame, *on_frame, fog->params) : frustum::Status{};
    case plan::Effect::Portal:
    case plan::Effect::Recursion:
        return draw_views(effect, ctx, frame, cameras.main.pair, options, window);
    case plan::Effect::Tiles:
        return draw_tiled_frame(ctx, frame, cameras.main.pair, options.tile_columns, options.tile_rows,
                                options.tile_borders);
    case plan::Effect::Frustum:
        return draw_frustums(ctx, cameras, options, window);
    }
    return {};
}

frustum::Status Renderer::draw_lens(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                    const frustum::MatrixPair<float>& camera, const RenderOptions& options) const {
    auto lens = plan::fit_lens(camera, lens_, bounds_, options.fit, options.lens_power);
    if (!lens) {
        return lens.take_error();
    }
    // The disc is hidden: the lens effect is the magnifier itself, and the
    // lens reference (reference/lens_reference.hpp) remaps a frame without it.
    const int disc = lens_ ? lens_->instance : -1;
    return draw_lens_frame(ctx, frame, LensDraw{camera, *lens, options.lens_grid, disc});
}

frustum::Status Renderer::draw_non_affine(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                          const frustum::MatrixPair<float>& camera,
                                          const RenderOptions& options) const {
    auto fitted = plan::fit_non_affine(camera, bounds_, options.nonaffine, options.fit);
    if (!fitted) {
        return fitted.take_error();
    }
    auto slits = plan::crossed_slits_frustum(camera, *fitted, ctx.depth.gpu_range());
    if (!slits) {
        return slits.take_error();
    }
    const plan::SplitGeometry& world = nonaffine_geometry_.get(gpu_scene_.instances(), fitted->max_edge_m);
    if (auto stats = draw_non_affine_frame(ctx, frame, world, *slits, *fitted); !stats) {
        return stats.take_error();
    }
    return {};
}

// Portal (one level) and recursion (options.recursion_depth levels): the
// view tree of the link group for the whole frame.
frustum::Status Renderer::draw_views(plan::Effect effect, const PassContext& ctx, const gl::OffscreenTarget& frame,
                                     const frustum::MatrixPair<float>& camera, const RenderOptions& options,
                                     const FrameWindow& window) const {
    auto group = link_group(effect, options, camera);
    if (!group) {
        return frustum::Error{group.error()};
    }
    const LinkGroup& g = **group;
    const int depth = effect == plan::Effect::Portal ? 1 : options.recursion_depth;
    auto nodes = plan::plan_view_tree(
        camera, g.links,
        plan::ViewTreeRequest{depth, window.full_width_px, window.full_height_px, plan::ViewBounds::Tight});
    if (!nodes) {
        return frustum::Error{nodes.error()};
    }
    return draw_recursion_frame(ctx, frame,
                                RecursionDraw{*nodes, g.links, g.quads, options.mirror_tint, &recursion_targets_});
}

// The main camera's frustum and the mirror's, seen from the overview camera.
frustum::Status Renderer::draw_frustums(const PassContext& ctx, const plan::Cameras& cameras,
                                        const RenderOptions& options, const FrameWindow& window) const {
    std::vector<FrustumOverlay> overlays{{cameras.main.pair, kMainFrustumColor}};
    if (mirror_) {
        auto reflection = plan::plan_reflection(*mirror_, cameras.main.pair, window.full_width_px,
                                                window.full_height_px, options.mirror_method, bounds_);
        if (!reflection) {
            return reflection.take_error();
        }
        if (*reflection) {
            overlays.push_back({(*reflection)->pair, kReflectionFrustumColor});
        }
    }
    auto viewer = crop_to_window(cameras.overview.pair, window);
    if (!viewer) {
        return viewer.take_error_in("render::Renderer::render_into()");
    }
    return draw_frustum_view(ctx, *viewer, overlays, line_style(bounds_));
}

} // namespace render
