// Tile-based rendering (paper §5.1): the frame as columns x rows tiles, each
// drawn with its cropped pair (frustum::crop_tiles) into its own viewport
// and scissor rectangle of one target. The stitched image equals the frame
// drawn whole: each tile pair maps its pixel rectangle to the full clip
// square, and the viewport maps it back.
#pragma once

#include "render/pass_context.hpp"

#include <frustum/crop.hpp>
#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <gl/offscreen_target.hpp>

#include <vector>

namespace render {

// Draws the scene once per tile, each into its own viewport and scissor
// rectangle with its own pair, after ONE clear of the whole frame (a
// scissored clear per tile costs a full-screen pass on some drivers:
// docs/performance.md). skip_instance as in SceneDraw. Shared by the crop
// tiles (§5.1) and the lens tiles (§5.4). The tiles are in the frame's
// pixels; with ctx.window set, each draws its part inside the window,
// cropped to it. Leaves `frame` bound with its full viewport and the scissor
// test off.
frustum::Status draw_tiles(const PassContext& ctx, const gl::OffscreenTarget& frame,
                           const std::vector<frustum::Tile<float>>& tiles, int skip_instance, const char* where);

// Paints a 1-pixel border along the left and bottom edge of every tile but
// the first column and row (so each seam is one line) in `color`, with
// scissored clears; `tiles` are in the frame's pixels and the bound target
// holds `window` of it. Leaves the scissor test off.
void draw_tile_borders(const PassContext& ctx, const FrameWindow& window,
                       const std::vector<frustum::Tile<float>>& tiles, const glm::vec4& color);

// Needs 1 <= columns <= frame width and 1 <= rows <= frame height (the
// whole frame's: ctx.window's full size when set). Leaves
// `frame` bound with its full viewport and the scissor test off.
// borders: draw_tile_borders() over the frame.
frustum::Status draw_tiled_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                 const frustum::MatrixPair<float>& camera, int columns, int rows,
                                 bool borders = false);

} // namespace render
