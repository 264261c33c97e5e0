#include "render/recursion_pass.hpp"

#include "render/mirror_pass.hpp"

#include <gl/errors.hpp>

#include <algorithm>
#include <optional>
#include <string>

namespace render {
namespace {

// A view's own target: its rectangle's size, sampled like the frame.
gl::OffscreenTargetOptions view_target(const PassContext& ctx, const ViewNode& node) {
    return {static_cast<int>(node.rect.width), static_cast<int>(node.rect.height), gl::ColorStorage::Texture,
            gl::DepthFormat::Depth24, ctx.samples};
}

struct Frame {
    const PassContext& ctx;
    const PassContext link_ctx; // the same, drawing the links' quads
    const RecursionDraw& draw;
    RecursionStats* stats;
    std::vector<std::optional<gl::OffscreenTarget>> textures; // per node, alive until its parent is drawn
};

// Node `index` into whatever is bound: the scene, the links' quads it does
// not look through, and its children's surfaces with their textures.
void draw_view(Frame& f, int index) {
    const ViewNode& node = f.draw.nodes[static_cast<std::size_t>(index)];
    DrawCounts* counts = f.stats ? &f.stats->per_level[static_cast<std::size_t>(node.level)] : nullptr;
    SceneDraw scene{node.render};
    scene.cull = node.cull;
    scene.clip_plane = node.clip_plane;
    scene.counts = counts;
    draw_scene(f.ctx, scene);

    SceneDraw quads{node.render};
    quads.clip_plane = node.clip_plane;
    if (node.link >= 0) { // the surface this view's near plane lies on
        const ViewLink& through = f.draw.links[static_cast<std::size_t>(node.link)];
        quads.skip_more.push_back(through.kind == ViewLink::Kind::Mirror ? through.surface_instance
                                                                          : through.exit_instance);
    }
    const std::vector<int> children = children_of(f.draw.nodes, index);
    for (int c : children) {
        quads.skip_more.push_back(f.draw.links[static_cast<std::size_t>(f.draw.nodes[static_cast<std::size_t>(c)].link)]
                                      .surface_instance);
    }
    draw_scene(f.link_ctx, quads);
    for (int c : children) {
        const ViewNode& child = f.draw.nodes[static_cast<std::size_t>(c)];
        const ViewLink& link = f.draw.links[static_cast<std::size_t>(child.link)];
        const glm::vec3 tint = link.kind == ViewLink::Kind::Mirror ? f.draw.tint : glm::vec3(1.0f);
        std::optional<gl::OffscreenTarget>& texture = f.textures[static_cast<std::size_t>(c)];
        draw_reflection_surface(f.link_ctx, node.render, link.surface_instance, texture->color_texture(),
                                child.surface_matrix, tint);
        if (f.draw.targets) {
            f.draw.targets->give_back(std::move(*texture), view_target(f.ctx, child));
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
    Frame f{ctx,
            PassContext{ctx.fn, ctx.api, ctx.programs, draw.link_scene, ctx.depth, ctx.lighting, ctx.clear_color,
                        ctx.samples},
            draw, stats, std::vector<std::optional<gl::OffscreenTarget>>(draw.nodes.size())};
    if (stats) {
        int levels = 0;
        for (const ViewNode& node : draw.nodes) {
            levels = std::max(levels, node.level + 1);
        }
        stats->per_level.assign(static_cast<std::size_t>(levels), DrawCounts{});
    }
    // ctx.pass_end hears "level k (n views)" as each view of level k >= 1
    // ends (level 0, the camera's view, is the caller's "main view").
    std::vector<std::string> level_names;
    if (ctx.pass_end) {
        std::vector<int> views;
        for (const ViewNode& node : draw.nodes) {
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
        const ViewNode& node = draw.nodes[i];
        const gl::OffscreenTargetOptions options = view_target(ctx, node);
        auto target = draw.targets ? draw.targets->take(ctx.fn, options) : gl::OffscreenTarget::create(ctx.fn, options);
        if (!target) {
            return frustum::Error{"render::draw_recursion_frame(): level " + std::to_string(node.level) +
                                  " texture: " + target.error()};
        }
        target->bind(); // a kept one is not bound yet (a new one is)
        begin_frame(ctx);
        draw_view(f, static_cast<int>(i));
        target->resolve();
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
