// Tile-based rendering (paper §5.1): the frame as columns x rows tiles, each
// drawn with its cropped pair (frustum::crop_tiles) into its own viewport
// and scissor rectangle of one target. The stitched image equals the frame
// drawn whole: each tile pair maps its pixel rectangle to the full clip
// square, and the viewport maps it back.
#pragma once

#include "render/pass_context.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <gl/offscreen_target.hpp>

namespace render {

// Needs 1 <= columns <= frame width and 1 <= rows <= frame height. Leaves
// `frame` bound with its full viewport and the scissor test off.
frustum::Status draw_tiled_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                 const frustum::MatrixPair<float>& camera, int columns, int rows);

} // namespace render
