// The pixel rectangle that bounds what a camera sees of a convex polygon
// (a mirror or portal quad), clipped in homogeneous clip space so that
// points behind the eye never get projected. A mirror or portal pass is
//   crop(mirror(camera, plane), *screen_rect(camera, quad, w, h))
// and a recursion level intersects its rectangle with its parent's
// (intersect below).
#pragma once

#include "frustum/crop.hpp"
#include "frustum/matrix_pair.hpp"
#include "frustum/result.hpp"

#include <optional>
#include <vector>

namespace frustum {

// Sutherland-Hodgman on the clip-space polygon h_i = M (p_i, 1) against
// the frustum's planes written in clip space (the pair keeps w > 0
// inside): w + x, w - x, w + y, w - y, s (z - z_n w) (near) and, when the
// far plane is finite, s (z_f w - z) (far), s = sign(z_f - z_n). Clipping
// by the near plane before dividing is what keeps a quad that crosses the
// eye plane honest: a vertex behind the eye has w < 0 and would project
// to the wrong side of the screen. What remains is divided by w, NDC
// [-1, 1] is mapped to [0, W] x [0, H] (from the BOTTOM-left, like crop),
// and its bounding box is returned as a CropRect with full_width = W,
// full_height = H (not rounded; it always lies inside the image, so it
// can be handed to crop() as it is).
//
// Empty (std::nullopt) when nothing of the polygon is visible, or only a
// segment or point (zero width or height: the polygon is seen edge-on).
// The polygon must be planar and convex for the result to be its exact
// visible bounding box; at least 3 finite points. Errors: fewer than 3
// points, a non-finite point, image sizes not finite and > 0.
template <class T>
Result<std::optional<CropRect<T>>> screen_rect(const MatrixPair<T>& pair, const std::vector<Vec3<T>>& polygon,
                                               T width_px, T height_px);

// The overlap of two rectangles of the same image (a recursion level's
// rectangle and its parent's); empty when they do not overlap with a
// positive area. Rectangles of different image sizes do not overlap.
template <class T>
std::optional<CropRect<T>> intersect(const CropRect<T>& a, const CropRect<T>& b);

} // namespace frustum
