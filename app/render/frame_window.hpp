// A target that holds one rectangle of a larger frame (a poster tile, paper
// §5.1): the passes plan every effect for the whole frame and draw, into the
// target, the crop of that plan to the rectangle. Screen-space intermediates
// (a reflection texture, a recursion view, a lens tile) are the frame's,
// intersected with the rectangle.
#pragma once

#include "plan/mirror_geometry.hpp"

#include <frustum/crop.hpp>
#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>

#include <glm/glm.hpp>

#include <optional>

namespace render {

struct FrameWindow {
    int full_width_px = 0, full_height_px = 0; // the whole frame
    plan::PixelRect rect;                      // the target's pixels in it, from the bottom-left
};

// The window of a target that holds the whole width_px x height_px frame.
FrameWindow whole_frame(int width_px, int height_px);

// The overlap of two pixel rectangles; empty when they do not overlap.
std::optional<plan::PixelRect> intersect(const plan::PixelRect& a, const plan::PixelRect& b);

// The smallest pixel rectangle holding both.
plan::PixelRect bounding(const plan::PixelRect& a, const plan::PixelRect& b);

// `r` in the target's pixels (offset by the window's corner).
plan::PixelRect in_target(const FrameWindow& window, const plan::PixelRect& r);

// A pair whose image is the frame rectangle `image` cropped (§5.1, eq.
// 14-15) to `part`, a rectangle inside `image` in the same frame pixels.
frustum::Result<frustum::MatrixPair<float>> crop_part(const frustum::MatrixPair<float>& pair,
                                                      const plan::PixelRect& image, const plan::PixelRect& part);

// crop_part() of the whole frame's pair to the window: what the target is drawn with.
frustum::Result<frustum::MatrixPair<float>> crop_to_window(const frustum::MatrixPair<float>& pair,
                                                           const FrameWindow& window);

// The forward half of crop_part() for a bare matrix (rows 0 and 1 of eq. 14:
// m0' = sx m0 + tx m3, m1' = sy m1 + ty m3), e.g. a recursion view's
// surface matrix, which has no inverse to keep.
glm::mat4 crop_part_matrix(const glm::mat4& matrix, const plan::PixelRect& image, const plan::PixelRect& part);

// The same map on normalized device coordinates, ndc' = ndc * xy + zw, for
// a shader that builds its clip position itself (non_affine.vert).
glm::vec4 window_ndc_scale_offset(const FrameWindow& window);

} // namespace render
