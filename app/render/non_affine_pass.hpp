// The non-affine effect (paper section 6): the scene through a frustum of six
// planes that no 4x4 matrix represents, mapped per vertex by eq. 36
// (shaders/non_affine.vert, frustum_non_affine_clip() in frustum.glsl).
//
// The frustum is a crossed-slits camera built from the main camera: its
// top, bottom, near and far planes, and left and right planes each turned
// about its own vertical axis so that they meet in a vertical line (the
// "slit") slit_depth_m in front of the eye instead of in the eye. Then
// horizontal positions are a perspective from the slit, vertical ones from
// the eye: no single centre of projection, so no matrix (eq. 9 fails).
//
// Remedy for the zero denominators (docs/non-affine.md): the triangles are
// split to at most max_edge_m per edge (eq. 36 bends straight edges; small
// triangles follow the curve), then every triangle with a vertex whose
// denominators are not all < -guard_m is dropped on the CPU.
#pragma once

#include "plan/non_affine_frustum.hpp"
#include "render/alpha_order.hpp"
#include "render/pass_context.hpp"
#include "plan/split_geometry.hpp"
#include "plan/world_geometry.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/non_affine.hpp>
#include <frustum/result.hpp>
#include <gl/objects.hpp>
#include <gl/offscreen_target.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace render {

struct NonAffineStats {
    int triangles = 0; // after subdivision
    int culled = 0;    // of them, dropped for a degenerate vertex
};

// True when some denominator of eq. 36 at `p` is >= -guard_m.
bool is_degenerate(const frustum::NonAffineFrustum<float>& frustum, const glm::vec3& p, float guard_m);

// The CPU part of one frame: the triangles of `geometry` that the cull keeps
// (options.cull: every triangle with a degenerate vertex is dropped), as
// indices into geometry.vertices, one range per primitive that keeps any.
struct NonAffineBatch {
    struct Range {
        std::uint32_t first = 0; // into indices
        std::uint32_t count = 0;
        std::size_t primitive = 0; // into geometry.split.primitives
    };
    std::vector<std::uint32_t> indices;
    std::vector<Range> ranges;
    NonAffineStats stats;
};
NonAffineBatch batch_non_affine(const plan::SplitGeometry& geometry, const frustum::NonAffineFrustum<float>& frustum,
                                const plan::NonAffineOptions& options);

// The CPU part on the GPU: the split's vertices and the batch's indices in
// one vertex array, with the ranges in draw order (opaque, masked, then
// blended back to front). A poster keeps one for all its tiles
// (FrameCache::non_affine).
struct NonAffineUpload {
    struct Range {
        GLsizei first = 0, count = 0; // into the index buffer
        const plan::WorldPrimitive* primitive = nullptr; // into the SplitGeometry uploaded
        AlphaGroup group = AlphaGroup::Opaque;
        float depth_m = 0.0f; // BLEND: distance of its centre behind the near plane
    };
    gl::VertexArray vertex_array;
    gl::Buffer vertex_buffer;
    gl::Buffer index_buffer;
    std::vector<Range> ranges;
    NonAffineStats stats;
};
frustum::Result<NonAffineUpload> upload_non_affine(const PassContext& ctx, const plan::SplitGeometry& geometry,
                                                  const frustum::NonAffineFrustum<float>& frustum,
                                                  const plan::NonAffineOptions& options);

// Draws the whole frame into `frame` (left bound); with ctx.frame_cache
// the cache's upload, made on its first tile. The frustum's planes are
// used; its depth range is not: s = 0..1 goes to the GPU's depth range
// (ctx.depth). `geometry` is the scene's triangles split to
// options.max_edge_m (SplitGeometry::build(), SplitGeometryCache).
frustum::Result<NonAffineStats> draw_non_affine_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                                      const plan::SplitGeometry& geometry,
                                                      const frustum::NonAffineFrustum<float>& frustum,
                                                      const plan::NonAffineOptions& options);

// As above from the scene's original (placed, unsplit) triangles: splits
// them first, each call.
frustum::Result<NonAffineStats> draw_non_affine_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                                      const plan::WorldGeometry& geometry,
                                                      const frustum::NonAffineFrustum<float>& frustum,
                                                      const plan::NonAffineOptions& options);

} // namespace render
