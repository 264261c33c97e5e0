#include "plan/view_tree.hpp"

#include "plan/mirror_geometry.hpp"

#include <frustum/mirror.hpp>
#include <frustum/portal.hpp>
#include <frustum/queries.hpp>
#include <frustum/screen_rect.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace plan {
namespace {

// The node's eye is strictly on the plane's positive side (a perspective eye only).
bool eye_in_front(const frustum::MatrixPair<float>& pair, const frustum::Plane<float>& plane) {
    const glm::vec4 eye = frustum::key_points(pair).eye;
    if (!(std::abs(eye.w) > 0.0f)) {
        return false;
    }
    return glm::dot(plane.abcd, eye / eye.w) > 0.0f;
}

// What frustum::clip_oblique() (src/oblique_clip.cpp) says when the link's
// plane has the whole view on its near side: through that link nothing is
// left to see, so the branch ends there (an empty view, not a failure).
constexpr const char* kNothingVisible = "clip plane leaves no part of the frustum visible";

bool nothing_visible(const std::string& error) { return error.find(kNothingVisible) != std::string::npos; }

struct Planner {
    const std::vector<ViewLink>& links;
    const ViewTreeRequest& request;
    std::vector<ViewNode> nodes;
    std::vector<frustum::CropRect<float>> visible; // per node: its tight rectangle
    std::optional<int> empty_from_level;           // the first level a branch ended at for want of a view

    frustum::Status visit(int index) {
        if (nodes[static_cast<std::size_t>(index)].level >= request.depth) {
            return {};
        }
        for (std::size_t li = 0; li < links.size(); ++li) {
            const ViewNode& node = nodes[static_cast<std::size_t>(index)];
            const ViewLink& link = links[li];
            if (link.kind == ViewLink::Kind::Mirror && static_cast<int>(li) == node.link) {
                continue;
            }
            const frustum::Plane<float> entry_plane = frustum::frame_plane(link.entry);
            if (!eye_in_front(node.full, entry_plane)) {
                continue;
            }
            auto seen = frustum::screen_rect(node.full, link.quad(), static_cast<float>(request.width_px),
                                             static_cast<float>(request.height_px));
            if (!seen) {
                return frustum::Error{seen.error()};
            }
            if (!*seen) {
                continue;
            }
            const auto pixels = whole_pixels(**seen);
            const auto rect = pixels ? frustum::intersect(*pixels, visible[static_cast<std::size_t>(index)])
                                     : std::nullopt;
            if (!rect) {
                continue;
            }
            auto added = add_child(index, static_cast<int>(li), *rect);
            if (!added) {
                return frustum::Error{added.error()};
            }
            if (!*added) {
                const int level = node.level + 1;
                empty_from_level = empty_from_level ? std::min(*empty_from_level, level) : level;
                continue;
            }
            if (auto status = visit(static_cast<int>(nodes.size()) - 1); !status) {
                return status;
            }
        }
        return {};
    }

    // false: through the link nothing of the view is left (kNothingVisible).
    frustum::Result<bool> add_child(int parent, int link_index, const frustum::CropRect<float>& rect) {
        const ViewNode& node = nodes[static_cast<std::size_t>(parent)];
        const ViewLink& link = links[static_cast<std::size_t>(link_index)];
        const bool mirror = link.kind == ViewLink::Kind::Mirror;
        const frustum::Plane<float> plane = link.near_plane();
        auto culling = mirror ? frustum::culling_pair(node.unclipped, plane, rect)
                              : frustum::culling_pair(node.unclipped, link.entry, link.exit, rect);
        auto full = mirror ? frustum::mirror(node.unclipped, plane)
                           : frustum::portal(node.unclipped, link.entry, link.exit);
        if (!culling || !full) {
            if (nothing_visible(!culling ? culling.error() : full.error())) {
                return false;
            }
            return frustum::Error{"plan::plan_view_tree(): level " + std::to_string(node.level + 1) + ": " +
                                  (!culling ? culling.error() : full.error())};
        }
        auto unclipped = frustum::uncrop(culling->pair, rect);
        auto cropped = frustum::crop(*full, rect);
        auto surface = frustum::crop(node.unclipped, rect);
        if (!unclipped || !cropped || !surface) {
            return frustum::Error{"plan::plan_view_tree(): " +
                                  (!unclipped ? unclipped.error() : !cropped ? cropped.error() : surface.error())};
        }
        ViewNode child(*full);
        child.parent = parent;
        child.link = link_index;
        child.level = node.level + 1;
        child.unclipped = *unclipped;
        if (request.bounds == ViewBounds::Tight) {
            child.rect = rect;
            child.render = *cropped;
            child.cull = culling->planes;
            child.surface_matrix = surface->matrix();
        } else {
            child.rect = visible.front();
            child.render = *unclipped;
            child.clip_plane = plane;
            child.surface_matrix = node.unclipped.matrix();
        }
        nodes.push_back(child);
        visible.push_back(rect);
        return true;
    }
};

} // namespace

frustum::Result<std::vector<ViewNode>> plan_view_tree(const frustum::MatrixPair<float>& camera,
                                                      const std::vector<ViewLink>& links,
                                                      const ViewTreeRequest& request) {
    auto plan = plan_views(camera, links, request);
    if (!plan) {
        return frustum::Error{plan.error()};
    }
    return std::move(plan->nodes);
}

frustum::Result<ViewTreePlan> plan_views(const frustum::MatrixPair<float>& camera, const std::vector<ViewLink>& links,
                                         const ViewTreeRequest& request) {
    if (request.depth < 0 || request.depth > kMaxRecursionDepth) {
        return frustum::Error{"plan::plan_view_tree(): depth " + std::to_string(request.depth) +
                              " must be in 0..8"};
    }
    if (request.width_px < 1 || request.height_px < 1) {
        return frustum::Error{"plan::plan_view_tree(): image " + std::to_string(request.width_px) + "x" +
                              std::to_string(request.height_px) + " must be at least 1x1 pixels"};
    }
    const float w = static_cast<float>(request.width_px), h = static_cast<float>(request.height_px);
    ViewNode root(camera);
    root.rect = {0.0f, 0.0f, w, h, w, h};
    if (request.bounds == ViewBounds::Tight) {
        root.cull = frustum::planes(camera);
    }
    Planner planner{links, request, {root}, {root.rect}, std::nullopt};
    if (auto status = planner.visit(0); !status) {
        return frustum::Error{status.error()};
    }
    return ViewTreePlan{std::move(planner.nodes), planner.empty_from_level};
}

frustum::Result<std::optional<std::string>> recursion_end_note(const frustum::MatrixPair<float>& camera,
                                                               const scene::Bounds& bounds,
                                                               const std::vector<scene::Bounds>& boxes, LinkSet set,
                                                               int depth, int width_px, int height_px) {
    auto links = place_facing_links(camera, bounds, set, boxes);
    if (!links) {
        return frustum::Error{links.error()};
    }
    auto plan = plan_views(camera, *links, ViewTreeRequest{depth, width_px, height_px, ViewBounds::Tight});
    if (!plan) {
        return frustum::Error{plan.error()};
    }
    if (!plan->empty_from_level) {
        return std::optional<std::string>{};
    }
    const int empty = *plan->empty_from_level;
    const std::string drawn = empty > 1 ? "; levels 1.." + std::to_string(empty - 1) + " drawn" : "";
    return std::optional<std::string>{"recursion: levels " + std::to_string(empty) + ".." + std::to_string(depth) +
                                      " are empty (through the links the view leaves nothing visible)" + drawn};
}

std::vector<int> children_of(const std::vector<ViewNode>& nodes, int index) {
    std::vector<int> out;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (nodes[i].parent == index) {
            out.push_back(static_cast<int>(i));
        }
    }
    return out;
}

} // namespace plan
