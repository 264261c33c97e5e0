// Draws every instance of the uploaded scene with one camera into whatever
// framebuffer and viewport are bound. The other passes are built from it.
#pragma once

#include "render/pass_context.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/plane.hpp>
#include <frustum/queries.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace render {

// Frame state shared by all passes: depth test on (window depth is [0, 1]
// whatever the clip range: GL_LESS against a clear value of 1), blending and
// scissor off, program point size on desktop GL.
void set_frame_state(const PassContext& ctx);

// Clears colour (ctx.clear_color) and depth; only inside the scissor
// rectangle when the scissor test is on.
void clear_frame(const PassContext& ctx);

// set_frame_state() then clear_frame().
void begin_frame(const PassContext& ctx);

// Primitives drawn and culled by draw_scene() calls.
struct DrawCounts {
    long drawn = 0;
    long culled = 0;
};

struct SceneDraw {
    explicit SceneDraw(const frustum::MatrixPair<float>& camera_pair) : camera(camera_pair) {}

    // Any depth range: the pass converts it with ctx.depth. A pair that
    // flips winding (a reflection) draws with the front face swapped.
    frustum::MatrixPair<float> camera;
    // World -> world transform applied after each instance's own, e.g. a
    // reflection matrix to draw the mirrored scene directly. The light is
    // part of the world and moves with it.
    glm::mat4 pre_model{1.0f};
    // World-space plane (after pre_model); fragments on its negative side
    // are discarded (the CLIP_PLANE program variant).
    std::optional<frustum::Plane<float>> clip_plane;
    int skip_instance = -1; // e.g. the mirror surface in its own reflection
    std::vector<int> skip_more; // further instances not drawn (a recursion's link surfaces)
    // Primitives whose world bounding box (the object-space box's eight
    // corners after the model) is Outside these planes are not drawn
    // (frustum::classify; a mirror or portal view's culling pair). Unset:
    // the camera's own planes (frustum::raw_planes(camera)).
    std::optional<frustum::FrustumPlanes<float>> cull;
    // When set, counts what was drawn and culled (adds to it).
    DrawCounts* counts = nullptr;
};

void draw_scene(const PassContext& ctx, const SceneDraw& draw);

} // namespace render
