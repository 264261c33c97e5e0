// The views of a recursion through mirrors and portals, planned on the CPU
// (docs/portals.md): node 0 is the camera; a node's children are the links
// it sees, each viewed with frustum::mirror() or frustum::portal() of the
// node's (uncropped) pair, cropped to the intersection of the link's
// screen rectangle (frustum::screen_rect) with the node's, and culled with
// frustum::culling_pair(). A branch stops at an empty rectangle or at the
// depth. Pure: no GL.
#pragma once

#include "plan/view_links.hpp"

#include <frustum/crop.hpp>
#include <frustum/culling.hpp>
#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>

#include <optional>
#include <string>
#include <vector>

namespace plan {

// How a view is bounded on screen.
enum class ViewBounds {
    // crop to the rectangle (intersected with the parent's), oblique near
    // plane = the link's near plane, cull with the culling pair.
    Tight,
    // what a Reflector chain or a stencil portal renderer does: every view
    // over the whole viewport, the link's plane as a fragment clip plane,
    // no oblique near plane and no culling. Same tree as Tight.
    FullViewport,
};

struct ViewNode {
    explicit ViewNode(const frustum::MatrixPair<float>& pair) : render(pair), full(pair), unclipped(pair) {}

    int parent = -1; // -1 for node 0, the camera
    int link = -1;   // the link this view looks through (into `links`)
    int level = 0;   // 0 = the camera, k = through k links
    frustum::CropRect<float> rect;        // whole pixels from the bottom-left; the full image for FullViewport
    frustum::MatrixPair<float> render;    // what the view is drawn with (cropped; uncropped for FullViewport)
    frustum::MatrixPair<float> full;      // the same view uncropped, oblique: what children are planned from
    frustum::MatrixPair<float> unclipped; // uncropped, no oblique plane: what culling pairs are built from
    std::optional<frustum::FrustumPlanes<float>> cull; // Tight: the culling pair's planes (node 0: the camera's)
    std::optional<frustum::Plane<float>> clip_plane;   // FullViewport: the link's near plane
    // The parent's camera cropped like `render`: maps a point of the link's
    // surface (the entry quad) to its place in this view's texture. For a
    // mirror it equals `render` on the mirror plane (the reflection fixes
    // it); for a portal `render` sees the exit, this sees the entry.
    glm::mat4 surface_matrix{1.0f};
};

inline constexpr int kMaxRecursionDepth = 8;

struct ViewTreeRequest {
    int depth = 4; // links passed through at most, 0..8
    int width_px = 0, height_px = 0;
    ViewBounds bounds = ViewBounds::Tight;
};

// Nodes in depth-first order (a child after its parent). A link is seen by
// a node when the node's eye is on the link's front and its quad's screen
// rectangle is not empty; a node does not look back into the mirror it came
// through (it would see that mirror's back). A branch also ends, cleanly,
// where the link's plane leaves nothing of the view beyond it (a view that
// looks back along the corridor, or through a far plane the links reach):
// that level and the deeper ones draw nothing there, the earlier ones draw.
// Errors: depth outside 0..8, image sizes < 1, or an error of the library's
// operations.
frustum::Result<std::vector<ViewNode>> plan_view_tree(const frustum::MatrixPair<float>& camera,
                                                      const std::vector<ViewLink>& links,
                                                      const ViewTreeRequest& request);

struct ViewTreePlan {
    std::vector<ViewNode> nodes;        // plan_view_tree()'s
    std::optional<int> empty_from_level; // the first level at which a branch ended with nothing visible
};

// plan_view_tree() with where it ended for want of a view (for --verbose).
frustum::Result<ViewTreePlan> plan_views(const frustum::MatrixPair<float>& camera, const std::vector<ViewLink>& links,
                                         const ViewTreeRequest& request);

// For --verbose: the recursion effect's links as the renderer places them
// for `camera` (place_facing_links() of `set`, unmoved) planned to `depth`
// at the frame size; empty when every branch ran its course, else e.g.
// "recursion: levels 3..4 are empty (through the links the view leaves
// nothing visible); levels 1..2 drawn".
frustum::Result<std::optional<std::string>> recursion_end_note(const frustum::MatrixPair<float>& camera,
                                                               const scene::Bounds& bounds,
                                                               const std::vector<scene::Bounds>& boxes, LinkSet set,
                                                               int depth, int width_px, int height_px);

// The children of node `index` (their indices into `nodes`).
std::vector<int> children_of(const std::vector<ViewNode>& nodes, int index);

} // namespace plan
