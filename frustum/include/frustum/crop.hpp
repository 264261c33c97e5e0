// Paper §5.1: crop a frustum to a sub-rectangle of its image (tiles,
// posters, a mirror's screen rectangle). Only rows 0 and 1 of M and columns
// 0, 1 and 3 of M^-1 change (the sparse form, eq. 15); the depth range is
// untouched, so crop works the same for every DepthRange.
#pragma once

#include "frustum/matrix_pair.hpp"
#include "frustum/result.hpp"

#include <cstddef>
#include <vector>

namespace frustum {

namespace detail {
struct TileGridWriter;
} // namespace detail

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

// The tiles of one image as a structure of arrays (the batched form, issue
// 14): the pixel edges of its columns and of its rows, and the tiles'
// matrices and inverses in two contiguous arrays, tile (column, row) at
// index() = row * columns() + column (row 0 is the bottom row). All tiles
// share the depth range and winding. Kept from frame to frame, a grid
// allocates nothing once it has held as many tiles.
template <class T>
class TileGrid {
public:
    int columns() const { return columns_; }
    int rows() const { return rows_; }
    std::size_t size() const { return matrices_.size(); }
    std::size_t index(int column, int row) const {
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column);
    }
    // A tile's viewport in whole pixels from the bottom-left, as glViewport takes it.
    int x_px(int column) const { return column_edges_px_[static_cast<std::size_t>(column)]; }
    int y_px(int row) const { return row_edges_px_[static_cast<std::size_t>(row)]; }
    int width_px(int column) const { return x_px(column + 1) - x_px(column); }
    int height_px(int row) const { return y_px(row + 1) - y_px(row); }
    // M and M^-1 of every tile, by index (one array each: a renderer can
    // upload all the matrices at once).
    const std::vector<Mat4<T>>& matrices() const { return matrices_; }
    const std::vector<Mat4<T>>& inverses() const { return inverses_; }
    // The pair and the Tile of the tile with this index (copies).
    MatrixPair<T> pair(std::size_t i) const;
    Tile<T> tile(std::size_t i) const;

private:
    friend struct detail::TileGridWriter;
    std::vector<int> column_edges_px_, row_edges_px_; // columns + 1 and rows + 1 edges
    std::vector<Mat4<T>> matrices_, inverses_;
    std::vector<Vec4<T>> scratch_; // per-column parts of the crop (crop_tiles)
    unsigned traits_ = 0;
    int columns_ = 0, rows_ = 0;
};

// Splits a width_px x height_px image into columns x rows tiles that cover
// it exactly (tile edges at floor(i W / columns)); each tile's pair is the
// crop of `pair` to it, with the bits crop() gives it. Needs
// 1 <= columns <= width_px, 1 <= rows <= height_px. The grid form writes
// into `out` (reusing its storage; left empty on an error).
template <class T>
Status crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns, int rows,
                  TileGrid<T>& out);
// The same as a vector of Tiles.
template <class T>
Result<std::vector<Tile<T>>> crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns,
                                        int rows);

} // namespace frustum
