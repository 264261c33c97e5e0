// Paper §5.1: crop a frustum to a sub-rectangle of its image (tiles,
// posters, a mirror's screen rectangle). Only rows 0 and 1 of M and columns
// 0, 1 and 3 of M^-1 change (the sparse form, eq. 15); the depth range is
// untouched, so crop works the same for every DepthRange.
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/result.hpp"

#include <vector>

namespace frustum {

// A sub-rectangle of the full image in any consistent unit (pixels,
// metres on the near plane, ...). The offset is from the BOTTOM-LEFT
// corner (docs/errata.md erratum 1; GL's image rows also start at the bottom).
template <class T>
struct CropRect {
    T x = 0, y = 0, width = 0, height = 0;
    T full_width = 0, full_height = 0;
};

// eq. 14-15 in column form, with w = W/bw, h = H/bh, x = X/bw, y = Y/bh:
//   m0' = w m0 + (w - 1 - 2x) m3           inv0' = inv0 / w
//   m1' = h m1 + (h - 1 - 2y) m3           inv1' = inv1 / h
//                                          inv3' = inv3 + (-1 + 1/w + 2x/w) inv0
//                                                       + (-1 + 1/h + 2y/h) inv1
// The rectangle must lie inside the image and have a positive size.
template <class T>
Result<MatrixPair<T>> crop(const MatrixPair<T>& pair, const CropRect<T>& rect);

// The inverse operation: the pair of the full image from the pair of one of
// its crops (crop(p, r) then uncrop(., r) gives p back).
template <class T>
Result<MatrixPair<T>> uncrop(const MatrixPair<T>& pair, const CropRect<T>& rect);

// One tile of an image split into columns x rows, in whole pixels, with its
// offset from the bottom-left (as glViewport takes it).
template <class T>
struct Tile {
    int column = 0, row = 0; // row 0 is the bottom row
    int x_px = 0, y_px = 0, width_px = 0, height_px = 0;
    MatrixPair<T> pair;
};

// Splits a width_px x height_px image into columns x rows tiles that cover
// it exactly (tile edges at floor(i W / columns)); each tile's pair is the
// crop of `pair` to it. Needs 1 <= columns <= width_px, 1 <= rows <= height_px.
template <class T>
Result<std::vector<Tile<T>>> crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns,
                                        int rows);

} // namespace frustum
