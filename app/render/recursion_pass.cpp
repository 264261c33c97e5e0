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

frustum::Result<std::vector<ViewPart>> view_parts(const std::vector<plan::ViewNode>& nodes, const FrameWindow& window) {
    std::vector<ViewPart> parts(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const plan::ViewNode& node = nodes[i];
        const plan::PixelRect rect = plan::pixel_rect(node.rect); // whole pixels (plan_view_tree())
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
    // A poster's tile (ctx.frame_cache): memory before reuse. Every view
    // draws into the poster's one multisampled canvas (FrameCache::
    // recursion_canvas) and is blitted into a colour-only texture of its
    // part's size, which waits for its parent (4x MSAA: 4 instead of 36
    // bytes a pixel for each waiting view, and no multisampled target made
    // per view and tile).
    gl::OffscreenTarget* canvas = nullptr;
    std::vector<std::string> level_names; // for ctx.pass_end, per level
};

// Node `index`'s own view into whatever is bound: the scene and the links'
// quads it does not look through (neither its own link's surface nor its
// children's, which composite_child() draws).
void draw_own(Frame& f, int index, const std::vector<int>& children) {
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
    for (int c : children) {
        quads.skip_more.push_back(f.draw.links[static_cast<std::size_t>(f.draw.nodes[static_cast<std::size_t>(c)].link)]
                                      .surface_instance);
    }
    draw_scene(f.link_ctx, quads);
}

// Child `c` of node `index`: its surface with its texture (drawn) into
// whatever is bound (node `index`'s view); then the texture goes.
void composite_child(Frame& f, int index, int c) {
    const plan::ViewNode& child = f.draw.nodes[static_cast<std::size_t>(c)];
    const ViewPart& child_part = f.parts[static_cast<std::size_t>(c)];
    const plan::ViewLink& link = f.draw.links[static_cast<std::size_t>(child.link)];
    const glm::vec3 tint = link.kind == plan::ViewLink::Kind::Mirror ? f.draw.tint : glm::vec3(1.0f);
    std::optional<gl::OffscreenTarget>& texture = f.textures[static_cast<std::size_t>(c)];
    draw_reflection_surface(f.link_ctx, *f.parts[static_cast<std::size_t>(index)].render, link.surface_instance,
                            texture->color_texture(), child_part.surface_matrix, tint);
    if (f.draw.targets && !f.canvas) {
        f.draw.targets->give_back(std::move(*texture), view_target(f.ctx, child_part));
    }
    texture.reset();
}

// Node `index`'s whole view into whatever is bound: its own, then each
// child's surface with the child's texture.
void draw_view(Frame& f, int index, const std::vector<int>& children) {
    draw_own(f, index, children);
    for (int c : children) {
        composite_child(f, index, c);
    }
}

// The children of `index` seen in the window.
std::vector<int> seen_children(const Frame& f, int index) {
    std::vector<int> seen;
    for (int c : plan::children_of(f.draw.nodes, index)) {
        if (f.parts[static_cast<std::size_t>(c)].part) {
            seen.push_back(c);
        }
    }
    return seen;
}

// The poster's canvas, made (again) when the frame's tile is larger than
// the one it has.
frustum::Result<gl::OffscreenTarget*> poster_canvas(const PassContext& ctx, FrameCache& cache,
                                                   const gl::OffscreenTarget& frame) {
    std::optional<gl::OffscreenTarget>& canvas = cache.recursion_canvas;
    if (!canvas || canvas->width() < frame.width() || canvas->height() < frame.height()) {
        const int width_px = std::max(frame.width(), canvas ? canvas->width() : 0);
        const int height_px = std::max(frame.height(), canvas ? canvas->height() : 0);
        canvas.reset(); // free the old one first
        auto made = gl::OffscreenTarget::create(
            ctx.fn, {width_px, height_px, gl::ColorStorage::Renderbuffer, gl::DepthFormat::Depth24, ctx.samples});
        if (!made) {
            return made.take_error_in("render::draw_recursion_frame(): canvas");
        }
        canvas = std::move(*made);
    }
    return &*canvas;
}

// Node `index` drawn on f.canvas, in its bottom-left part's size, then
// blitted into a colour-only texture of that size, returned.
frustum::Result<gl::OffscreenTarget> draw_on_canvas(Frame& f, int index, const std::vector<int>& children) {
    const plan::PixelRect& part = *f.parts[static_cast<std::size_t>(index)].part;
    const gl::Functions& fn = f.ctx.fn;
    f.canvas->bind();
    fn.Viewport(0, 0, part.width, part.height);
    set_frame_state(f.ctx);
    fn.Enable(GL_SCISSOR_TEST); // clear the part only
    fn.Scissor(0, 0, part.width, part.height);
    clear_frame(f.ctx);
    fn.Disable(GL_SCISSOR_TEST);
    draw_view(f, index, children);
    auto texture = gl::OffscreenTarget::create(
        fn, {part.width, part.height, gl::ColorStorage::Texture, gl::DepthFormat::None, 1});
    if (!texture) {
        return texture.take_error();
    }
    if (auto blit = f.canvas->blit_color_to(*texture, part.width, part.height); !blit) {
        return blit.take_error();
    }
    return texture;
}

// Node `index` (>= 1) and all it sees through its links into
// f.textures[index]: its children first, depth first, each composited as
// soon as its parent is drawn, so that only the textures along one path of
// the tree wait at a time, not a whole level's.
frustum::Status draw_into_texture(Frame& f, int index, TargetPool* pool) {
    const plan::ViewNode& node = f.draw.nodes[static_cast<std::size_t>(index)];
    const std::vector<int> children = seen_children(f, index);
    for (int c : children) {
        if (auto status = draw_into_texture(f, c, pool); !status) {
            return status;
        }
    }
    frustum::Result<gl::OffscreenTarget> target = frustum::Error{""};
    if (f.canvas) {
        target = draw_on_canvas(f, index, children);
    } else {
        const gl::OffscreenTargetOptions options = view_target(f.ctx, f.parts[static_cast<std::size_t>(index)]);
        target = pool ? pool->take(f.ctx.fn, options) : gl::OffscreenTarget::create(f.ctx.fn, options);
        if (target) {
            target->bind(); // a kept one is not bound yet (a new one is)
            begin_frame(f.ctx);
            draw_view(f, index, children);
            target->resolve();
        }
    }
    if (!target) {
        return frustum::Error{"render::draw_recursion_frame(): level " + std::to_string(node.level) +
                              " texture: " + target.error()};
    }
    f.textures[static_cast<std::size_t>(index)] = std::move(*target);
    if (f.ctx.pass_end) {
        f.ctx.pass_end(f.level_names[static_cast<std::size_t>(node.level)].c_str());
    }
    return {};
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
            draw, stats, std::move(*parts), std::vector<std::optional<gl::OffscreenTarget>>(draw.nodes.size()),
            nullptr, {}};
    if (ctx.frame_cache) {
        auto canvas = poster_canvas(ctx, *ctx.frame_cache, frame);
        if (!canvas) {
            return canvas.take_error();
        }
        f.canvas = *canvas;
    }
    TargetPool* pool = f.canvas ? nullptr : draw.targets;
    if (stats) {
        int levels = 0;
        for (const plan::ViewNode& node : draw.nodes) {
            levels = std::max(levels, node.level + 1);
        }
        stats->per_level.assign(static_cast<std::size_t>(levels), DrawCounts{});
    }
    // ctx.pass_end hears "level k (n views)" as each view of level k >= 1
    // ends (level 0, the camera's view, is the caller's "main view").
    if (ctx.pass_end) {
        std::vector<int> views;
        for (const plan::ViewNode& node : draw.nodes) {
            views.resize(std::max(views.size(), static_cast<std::size_t>(node.level) + 1), 0);
            ++views[static_cast<std::size_t>(node.level)];
        }
        for (std::size_t level = 0; level < views.size(); ++level) {
            f.level_names.push_back("level " + std::to_string(level) + " (" + std::to_string(views[level]) +
                                    (views[level] == 1 ? " view)" : " views)"));
        }
    }
    // The camera's own view first, then each child's subtree into its
    // texture and at once onto the frame.
    frame.bind();
    begin_frame(ctx);
    const std::vector<int> children = seen_children(f, 0);
    draw_own(f, 0, children);
    for (int c : children) {
        if (auto status = draw_into_texture(f, c, pool); !status) {
            return status;
        }
        frame.bind();
        set_frame_state(ctx);
        composite_child(f, 0, c);
    }
    if (draw.targets) {
        draw.targets->end_frame();
    }
    return gl::check_error(ctx.fn, "render::draw_recursion_frame()");
}

} // namespace render
