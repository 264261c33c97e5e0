// Draws a planned view tree (view_tree.hpp): the portal effect (one portal
// pair, depth 1) and the recursion effect (facing mirrors or a portal
// facing itself, depth N). Each view but the camera's is rendered into a
// texture of its rectangle's size, deepest first; a view draws the scene
// (culled with its culling pair), the links' quads, and the surfaces of its
// children with their textures (mirror_composite shaders). With
// ctx.pass_end set, each view of level k >= 1 ends a pass named
// "level k (n views)" (n: the level's views), so a GPU timer or fragment
// counter gets every level's views under one name.
#pragma once

#include "render/pass_context.hpp"
#include "render/scene_pass.hpp"
#include "render/target_pool.hpp"
#include "plan/view_links.hpp"
#include "plan/view_tree.hpp"

#include <frustum/result.hpp>
#include <gl/offscreen_target.hpp>

#include <glm/glm.hpp>

#include <vector>

namespace render {

struct RecursionDraw {
    const std::vector<plan::ViewNode>& nodes; // plan_view_tree() for the frame's size
    const std::vector<plan::ViewLink>& links; // their surfaces are instances of `link_scene`
    const GpuScene& link_scene;               // link_scene(links) uploaded
    glm::vec3 tint{0.92f, 0.95f, 1.0f};       // a mirror's reflection times this; portals show theirs untinted
    // The views' targets come from here and go back when composited
    // (end_frame() at the end); null: made and freed per view.
    TargetPool* targets = nullptr;
};

// Per level (index = level) what draw_recursion_frame() drew.
struct RecursionStats {
    std::vector<DrawCounts> per_level;
};

// Draws the frame into `frame` (left bound); fills `stats` when given.
frustum::Status draw_recursion_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                     const RecursionDraw& draw, RecursionStats* stats = nullptr);

} // namespace render
