// Sub-pixel jitter (TAA): the image shifted by (dx_px, dy_px) pixels, with
// its inverse analytic. Like crop (§5.1) it only touches clip x and y:
//
//   J = | 1 0 0 2 dx/W |     J^-1 = | 1 0 0 -2 dx/W |
//       | 0 1 0 2 dy/H |            | 0 1 0 -2 dy/H |
//       | 0 0 1   0    |            | 0 0 1    0    |
//       | 0 0 0   1    |            | 0 0 0    1    |
//
//   M' = J M  (row 0 += 2 dx/W row 3, row 1 += 2 dy/H row 3),
//   M'^-1 = M^-1 J^-1 (column 3 -= 2 dx/W column 0 + 2 dy/H column 1).
// Positive dx, dy move the picture right and up (clip x' = x + (2 dx/W) w).
//
// Composable with every other operation. J acts on clip space from the
// left; reflect and the portal carry act on world space from the right
// (M R, M T), so they commute with it exactly. Crop and jitter commute
// when the jitter is given in the pixels of the image it applies to:
//   jitter(crop(p, r), dx, dy, r.width, r.height)
//     == crop(jitter(p, dx, dy, r.full_width, r.full_height), r).
// clip_oblique keeps rows 0, 1 and 3 and rewrites row 2 as
// (z_f - z_n) k c + z_n m3 with k from the far corner Q = M^-1 q, so
// clip(J X) and J clip(X) have the same image shift and the same near
// plane; only k, the tilt of the far plane, differs (Q is the jittered or
// the unjittered far corner). An engine wants jitter LAST,
// jitter(mirror(camera), ...): the reflection pass is then the fixed
// unjittered mirror pair shifted by exactly the main pass's J, so its
// depth (far plane included) does not wobble from frame to frame and the
// unjittered mirror pair reprojects its history; mirror(jitter(camera))
// re-tilts the far plane every frame.
//
// TAA: keep the caller's unjittered pair for reprojection and motion
// vectors (history lookup with the previous frame's unjittered pair), and
// render with jitter(pair, halton_x - 0.5, halton_y - 0.5, W, H); the
// jittered inverse unprojects a pixel centre onto the ray of the jittered
// pixel (tests/math/jitter_test.cpp).
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/result.hpp"

namespace frustum {

// dx_px, dy_px: any finite reals; width_px, height_px: positive and finite.
template <class T>
Result<MatrixPair<T>> jitter(const MatrixPair<T>& pair, T dx_px, T dy_px, T width_px, T height_px);

// The radical inverse of `index` (>= 0) in `base` (>= 2): the Halton
// sequence's coordinate, in [0, 1).
inline double radical_inverse(int index, int base) {
    double scale = 1, value = 0;
    for (; index > 0; index /= base) {
        scale /= base;
        value += scale * (index % base);
    }
    return value;
}

// The usual TAA offsets: Halton(2,3) sample `index` minus 1/2, in pixels,
// each in [-1/2, 1/2). TAA cycles through indices 1..8 (or 1..16); index 0
// is the pixel's corner (-1/2, -1/2).
template <class T>
Vec2<T> halton_jitter_px(int index) {
    return Vec2<T>(T(radical_inverse(index, 2) - 0.5), T(radical_inverse(index, 3) - 0.5));
}

} // namespace frustum
