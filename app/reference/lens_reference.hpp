// The per-pixel reference of the lens effect (paper section 5.4). All rays
// share the eye, so the exact lens image is a 2D remap of the unwarped view:
// the pixel at near-plane point X shows what the camera sees through
// X' = lens_warp(X) (eq. 34). The unwarped view is rendered into textures at
// `supersampling` times the frame's resolution, and shaders/lens_remap.frag
// looks X' up per pixel (bilinear).
//
// eq. 34 pushes points outside the lens radius away from it (r^p grows), so
// X' can lie far outside the camera's near rectangle. The view is therefore
// rendered through nested near-plane rectangles of 1, 2, 4, ... times the
// camera's, each into its own texture of the same size, until one holds the
// warped image of every pixel centre; each pixel takes the narrowest
// (sharpest) rectangle holding its X'. Level l has 2^-l of the texel density
// of level 0, which is what the minifying outer region needs.
//
// Limits: bilinear lookups blur what the tiles render sharply by up to half
// a texel (1 / (2 supersampling) pixel at level 0); where eq. 34 magnifies
// strongly (the lens centre for p > 1) that blur is magnified too.
#pragma once

#include "render/lens_pass.hpp"
#include "render/pass_context.hpp"

#include <frustum/result.hpp>
#include <gl/offscreen_target.hpp>

namespace reference {

inline constexpr int kMaxLensReferenceLevels = 12;

// Draws the whole frame into `frame` (left bound); draw.grid is not used.
// Returns how many nested levels it needed. Errors: supersampling outside
// 1..8, more than kMaxLensReferenceLevels levels, textures too large.
frustum::Result<int> draw_lens_reference(const render::PassContext& ctx, const gl::OffscreenTarget& frame,
                                         const render::LensDraw& draw, int supersampling);

} // namespace reference
