// The curved-mirror effect (paper §4.3): a convex cap over the planar
// mirror's rectangle, reflected patch by patch. Each of the G x G patches
// gets the frustum plan_curved_mirror() fits to its reflected volume; the
// scene is rendered once per patch with it (an ordinary, unmirrored view
// from the patch origin O behind the mirror: no reflection matrix, no
// winding flip, like frustum::mirror_rectangle) into the patch's view, a
// texture of its own. Then the frame: the scene without the planar mirror's
// surface, and the cap, each fragment of patch (i, j) projecting its own
// world position with that patch's matrix into the patch's view. The
// fragment is not on the patch frustum's near plane (the cap bulges in
// front of its corners' plane by up to the patch's own sagitta): the lookup
// follows the ray O -> fragment, which is the approximation the fitted
// frustum makes, not the fragment's exactly reflected ray.
#pragma once

#include "plan/curved_mirror.hpp"
#include "plan/mirror_geometry.hpp"
#include "render/pass_context.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <gl/objects.hpp>
#include <gl/offscreen_target.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace render {

struct CurvedDraw {
    frustum::MatrixPair<float> camera;  // ZeroToOne, perspective
    scene::MirrorRect mirror;           // the cap's footprint; mirror.instance is not drawn
    plan::CurvedMirrorOptions options;
    glm::vec3 tint{0.92f, 0.95f, 1.0f}; // times the reflection
    scene::Bounds bounds;               // the patch frustums' far planes lie beyond it
};

// The cap as one indexed triangle mesh (curved_pass.cpp: upload_cap()).
struct CapMesh {
    gl::VertexArray vertex_array;
    gl::Buffer vertex_buffer, index_buffer;
};

// What the curved mirror plans once per frame (a poster's tiles share it,
// frame_cache.hpp): the patches' fits, the cap's mesh, and the patches'
// views. Patch k's view (index j G + i) is `tile` texels, kept as strips of
// `strip_rows` texel rows (what the first target drawn into holds, less
// two: a direct render's whole view, a poster tile's height), each a
// colour-only texture with a row of margin above and below (for the
// bilinear lookup). A strip is made when a target first shows a fragment
// that samples it and let go when a target's rows of the frame do not any
// more (a poster's tiles come a row of tiles at a time), so a poster holds
// only the strips its current row of tiles samples, not all G^2 views.
struct CurvedViews {
    // A quad of the cap mesh: the frame pixels its two triangles can reach
    // and the view rows their lookups can read (first and last, inclusive),
    // each rounded out by one.
    struct Quad {
        plan::PixelRect screen;
        int first_row = 0, last_row = 0;
    };
    std::optional<plan::CurvedPlan> plan; // empty: the eye is behind the footprint, the frame is plain
    CapMesh cap;
    glm::ivec2 tile{0}; // curved_tile_size()
    int strip_rows = 0;
    int strips_per_patch = 0;
    int quads_per_patch = 0; // of the cap mesh
    // Per patch, its quads; empty (not needed) when the frame is drawn
    // whole in one target holding each view in one strip: then every quad
    // is drawn and reads strip 0.
    std::vector<std::vector<Quad>> quads;
    std::vector<std::optional<gl::OffscreenTarget>> strips; // patch k's strip s at k strips_per_patch + s
};

// Patch views: width along a1, height along a2, each the longest on-screen
// length of a patch edge in that direction (so a texel is never larger than
// a screen pixel), at least 4 and at most 4096 / G texels.
glm::ivec2 curved_tile_size(const plan::CurvedMirror& mirror, const frustum::MatrixPair<float>& camera, int grid,
                            int width_px, int height_px);

// Draws the whole frame into `frame` (left bound). When the eye is behind
// the footprint's plane the frame is the plain scene, with the planar
// mirror's surface. A patch without a frustum (seen from behind, or its fit
// failed) shows the clear colour.
frustum::Status draw_curved_mirror_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                         const CurvedDraw& draw);

} // namespace render
