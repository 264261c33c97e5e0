#include "render/recursion_pass.hpp"

#include "render/mirror_pass.hpp"

#include <gl/errors.hpp>

#include <algorithm>
#include <optional>
#include <string>

namespace render {
namespace {

// What a view draws into the target's window (frame_window.hpp): its
// rectangle (whole frame pixels, the planner's) intersected with the
// window, its pair and its surface matrix cropped to that part (§5.1). Every
// view is planned for the whole frame; a view whose rectangle misses the
// window is not drawn (its surface shows no pixel there either: the
// rectangle bounds it).
struct ViewPart {
    std::optional<plan::PixelRect> part;
    std::optional<frustum::MatrixPair<float>> render;
    glm::mat4 surface_matrix{1.0f};
};

plan::PixelRect whole_pixels(const frustum::CropRect<float>& r) {
    return {static_cast<int>(r.x), static_cast<int>(r.y), static_cast<int>(r.width), static_cast<int>(r.height)};
}

frustum::Result<std::vector<ViewPart>> view_parts(const std::vector<plan::ViewNode>& nodes, const FrameWindow& window) {
    std::vector<ViewPart> parts(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const plan::ViewNode& node = nodes[i];
        const plan::PixelRect rect = whole_pixels(node.rect);
        parts[i].part = intersect(rect, window.rect);
        if (!parts[i].part) {
            continue;
        }
        auto render = crop_part(node.render, rect, *parts[i].part);
        if (!render) {
            return render.take_error_in("render::draw_recursion_frame()");
        }
        parts[i].render = *render;
        const bool whole = parts[i].part->width == rect.width && parts[i].part->height == rect.height;
        parts[i].surface_matrix = whole ? node.surface_matrix
                                        : crop_part_matrix(node.surface_matrix, rect, *parts[i].part);
    }
    return parts;
}

// A view's own target: its part's size, sampled like the frame.
gl::OffscreenTargetOptions view_target(const PassContext& ctx, const ViewPart& view) {
    return {view.part->width, view.part->height, gl::ColorStorage::Texture, gl::DepthFormat::Depth24, ctx.samples};
}

struct Frame {
    const PassContext& ctx;
    const PassContext link_ctx; // the same, drawing the links' quads
    const RecursionDraw& draw;
    RecursionStats* stats;
    std::vector<ViewPart> parts;                              // per node
    std::vector<std::optional<gl::OffscreenTarget>> textures; // per node, alive until its parent is drawn
    // A poster's tile (ctx.frame_cache): memory before reuse. Each view's
    // target keeps only its resolved colour once drawn and is not pooled, so
    // one multisampled target is alive at a time instead of a frame's set
    // (4x MSAA: 4 instead of 36 bytes a pixel for each waiting view).
    bool lean = false;
};

// Node `index` into whatever is bound: the scene, the links' quads it does
// not look through, and its children's surfaces with their textures.
void draw_view(Frame& f, int index) {
    const plan::ViewNode& node = f.draw.nodes[static_cast<std::size_t>(index)];
    const frustum::MatrixPair<float>& render = *f.parts[static_cast<std::size_t>(index)].render;
    DrawCounts* counts = f.stats ? &f.stats->per_level[static_cast<std::size_t>(node.level)] : nullptr;
    SceneDraw scene{render};
    scene.cull = node.cull;
    scene.clip_plane = node.clip_plane;
    scene.counts = counts;
    draw_scene(f.ctx, scene);

    SceneDraw quads{render};
    quads.clip_plane = node.clip_plane;
    if (node.link >= 0) { // the surface this view's near plane lies on
        const plan::ViewLink& through = f.draw.links[static_cast<std::size_t>(node.link)];
        quads.skip_more.push_back(through.kind == plan::ViewLink::Kind::Mirror ? through.surface_instance
                                                                          : through.exit_instance);
    }
    const std::vector<int> children = plan::children_of(f.draw.nodes, index);
    for (int c : children) {
        quads.skip_more.push_back(f.draw.links[static_cast<std::size_t>(f.draw.nodes[static_cast<std::size_t>(c)].link)]
                                      .surface_instance);
    }
    draw_scene(f.link_ctx, quads);
    for (int c : children) {
        const plan::ViewNode& child = f.draw.nodes[static_cast<std::size_t>(c)];
        const ViewPart& child_part = f.parts[static_cast<std::size_t>(c)];
        if (!child_part.part) {
            continue; // outside the window
        }
        const plan::ViewLink& link = f.draw.links[static_cast<std::size_t>(child.link)];
        const glm::vec3 tint = link.kind == plan::ViewLink::Kind::Mirror ? f.draw.tint : glm::vec3(1.0f);
        std::optional<gl::OffscreenTarget>& texture = f.textures[static_cast<std::size_t>(c)];
        draw_reflection_surface(f.link_ctx, render, link.surface_instance, texture->color_texture(),
                                child_part.surface_matrix, tint);
        if (f.draw.targets && !f.lean) {
            f.draw.targets->give_back(std::move(*texture), view_target(f.ctx, child_part));
        }
        texture.reset();
    }
}

} // namespace

frustum::Status draw_recursion_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                     const RecursionDraw& draw, RecursionStats* stats) {
    if (draw.nodes.empty()) {
        return frustum::Error{"render::draw_recursion_frame(): no views (plan_view_tree() gives at least the camera)"};
    }
    auto parts = view_parts(draw.nodes, window_of(ctx, frame.width(), frame.height()));
    if (!parts) {
        return frustum::Error{parts.error()};
    }
    Frame f{ctx,
            PassContext{ctx.fn, ctx.api, ctx.programs, draw.link_scene, ctx.depth, ctx.lighting, ctx.clear_color,
                        ctx.samples},
            draw, stats, std::move(*parts), std::vector<std::optional<gl::OffscreenTarget>>(draw.nodes.size())};
    f.lean = ctx.frame_cache != nullptr;
    TargetPool* pool = f.lean ? nullptr : draw.targets;
    if (stats) {
        int levels = 0;
        for (const plan::ViewNode& node : draw.nodes) {
            levels = std::max(levels, node.level + 1);
        }
        stats->per_level.assign(static_cast<std::size_t>(levels), DrawCounts{});
    }
    // ctx.pass_end hears "level k (n views)" as each view of level k >= 1
    // ends (level 0, the camera's view, is the caller's "main view").
    std::vector<std::string> level_names;
    if (ctx.pass_end) {
        std::vector<int> views;
        for (const plan::ViewNode& node : draw.nodes) {
            views.resize(std::max(views.size(), static_cast<std::size_t>(node.level) + 1), 0);
            ++views[static_cast<std::size_t>(node.level)];
        }
        for (std::size_t level = 0; level < views.size(); ++level) {
            level_names.push_back("level " + std::to_string(level) + " (" + std::to_string(views[level]) +
                                  (views[level] == 1 ? " view)" : " views)"));
        }
    }
    // Children come after their parents: the deepest views are drawn first.
    for (std::size_t i = draw.nodes.size(); i-- > 1;) {
        const plan::ViewNode& node = draw.nodes[i];
        if (!f.parts[i].part) {
            continue; // outside the window: nothing of it is seen there
        }
        const gl::OffscreenTargetOptions options = view_target(ctx, f.parts[i]);
        auto target = pool ? pool->take(ctx.fn, options) : gl::OffscreenTarget::create(ctx.fn, options);
        if (!target) {
            return frustum::Error{"render::draw_recursion_frame(): level " + std::to_string(node.level) +
                                  " texture: " + target.error()};
        }
        target->bind(); // a kept one is not bound yet (a new one is)
        begin_frame(ctx);
        draw_view(f, static_cast<int>(i));
        if (f.lean) {
            target->keep_resolved_only();
        } else {
            target->resolve();
        }
        f.textures[i] = std::move(*target);
        if (ctx.pass_end) {
            ctx.pass_end(level_names[static_cast<std::size_t>(node.level)].c_str());
        }
    }
    frame.bind();
    begin_frame(ctx);
    draw_view(f, 0);
    if (draw.targets) {
        draw.targets->end_frame();
    }
    return gl::check_error(ctx.fn, "render::draw_recursion_frame()");
}

} // namespace render
