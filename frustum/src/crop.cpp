#include "frustum/crop.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/pair_updates.hpp"

#include <cmath>

namespace frustum {

using detail::crop_map;
using detail::CropMap;

template <class T>
Result<MatrixPair<T>> crop(const MatrixPair<T>& pair, const CropRect<T>& rect) {
    if (!detail::crop_rect_is_valid(rect)) {
        return detail::crop_rect_error(rect, "crop");
    }
    const CropMap<T> c = crop_map(rect);
    return detail::scale_offset_xy(pair, c.sx, c.tx, c.sy, c.ty);
}

template <class T>
Result<MatrixPair<T>> uncrop(const MatrixPair<T>& pair, const CropRect<T>& rect) {
    if (!detail::crop_rect_is_valid(rect)) {
        return detail::crop_rect_error(rect, "uncrop");
    }
    // invCropMat of eq. 14: x = (x' - t w) / s.
    const CropMap<T> c = crop_map(rect);
    return detail::scale_offset_xy(pair, T(1) / c.sx, -c.tx / c.sx, T(1) / c.sy, -c.ty / c.sy);
}

namespace {

// What one column of tiles shares: row 0 of M' and columns 0 and 3 (its
// first term) of the inverse; one row of tiles likewise row 1 of M' and the
// term of column 1. The same expressions as detail::scale_offset_xy, in the
// same order, so every tile has the bits crop() gives it.
template <class T>
struct TileColumn {
    Vec4<T> row0; // entry j: row 0 of column j of M'
    Vec4<T> inv0, inv3_partial;
    int x0, width;
};
template <class T>
struct TileRow {
    Vec4<T> row1;
    Vec4<T> inv1, inv3_term;
    int y0, height;
};

int tile_edge(int i, int size, int count) {
    return static_cast<int>(static_cast<long long>(i) * size / count);
}

} // namespace

template <class T>
Result<std::vector<Tile<T>>> crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns,
                                        int rows) {
    if (width_px < 1 || height_px < 1 || columns < 1 || rows < 1 || columns > width_px || rows > height_px) {
        return detail::error<T>("crop_tiles", "need 1 <= columns <= width_px and 1 <= rows <= height_px",
                                {{"width_px", T(width_px)}, {"height_px", T(height_px)},
                                 {"columns", T(columns)}, {"rows", T(rows)}});
    }
    const Mat4<T>& m = pair.matrix();
    const Mat4<T>& inv = pair.inverse();
    // Batched (issue 14): the per-axis crop maps are computed once per
    // column and once per row of tiles; a tile only assembles its columns.
    std::vector<TileColumn<T>> tile_columns(static_cast<std::size_t>(columns));
    for (int c = 0; c < columns; ++c) {
        const int x0 = tile_edge(c, width_px, columns), x1 = tile_edge(c + 1, width_px, columns);
        const CropMap<T> map = crop_map(CropRect<T>{T(x0), T(0), T(x1 - x0), T(1), T(width_px), T(1)});
        const T inv_sx = T(1) / map.sx;
        TileColumn<T>& out = tile_columns[static_cast<std::size_t>(c)];
        for (int j = 0; j < 4; ++j) {
            out.row0[j] = m[j].x * map.sx + m[j].w * map.tx;
        }
        out.inv0 = inv[0] * inv_sx;
        out.inv3_partial = inv[3] - (map.tx * inv_sx) * inv[0];
        out.x0 = x0;
        out.width = x1 - x0;
    }
    std::vector<TileRow<T>> tile_rows(static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r) {
        const int y0 = tile_edge(r, height_px, rows), y1 = tile_edge(r + 1, height_px, rows);
        const CropMap<T> map = crop_map(CropRect<T>{T(0), T(y0), T(1), T(y1 - y0), T(1), T(height_px)});
        const T inv_sy = T(1) / map.sy;
        TileRow<T>& out = tile_rows[static_cast<std::size_t>(r)];
        for (int j = 0; j < 4; ++j) {
            out.row1[j] = m[j].y * map.sy + m[j].w * map.ty;
        }
        out.inv1 = inv[1] * inv_sy;
        out.inv3_term = (map.ty * inv_sy) * inv[1];
        out.y0 = y0;
        out.height = y1 - y0;
    }
    // Rows 2 and 3 of M' and column 2 of the inverse are every tile's:
    // M_j.z * 1 + M_j.w * 0 and M_j.w * 1 + M_j.w * 0 as crop() forms them.
    Vec4<T> row2, row3;
    for (int j = 0; j < 4; ++j) {
        row2[j] = m[j].z * T(1) + m[j].w * T(0);
        row3[j] = m[j].w * T(1) + m[j].w * T(0);
    }
    const unsigned traits = detail::PairFactory::traits(pair);

    std::vector<Tile<T>> tiles;
    tiles.reserve(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r) {
        const TileRow<T>& tr = tile_rows[static_cast<std::size_t>(r)];
        for (int c = 0; c < columns; ++c) {
            const TileColumn<T>& tc = tile_columns[static_cast<std::size_t>(c)];
            tiles.push_back(Tile<T>{
                c, r, tc.x0, tr.y0, tc.width, tr.height,
                detail::PairFactory::keep_sign_columns<T>(
                    Vec4<T>(tc.row0[0], tr.row1[0], row2[0], row3[0]), Vec4<T>(tc.row0[1], tr.row1[1], row2[1], row3[1]),
                    Vec4<T>(tc.row0[2], tr.row1[2], row2[2], row3[2]), Vec4<T>(tc.row0[3], tr.row1[3], row2[3], row3[3]),
                    tc.inv0, tr.inv1, inv[2], tc.inv3_partial - tr.inv3_term, traits)});
        }
    }
    return tiles;
}

#define FRUSTUM_INSTANTIATE(T)                                                                   \
    template Result<MatrixPair<T>> crop(const MatrixPair<T>&, const CropRect<T>&);               \
    template Result<MatrixPair<T>> uncrop(const MatrixPair<T>&, const CropRect<T>&);             \
    template Result<std::vector<Tile<T>>> crop_tiles(const MatrixPair<T>&, int, int, int, int);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
