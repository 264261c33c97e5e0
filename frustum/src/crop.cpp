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
    return detail::crop_pair(pair, rect);
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

// What one column of tiles shares: rows 0, 2 and 3 of M' (row 1 left 0)
// and columns 0 and 3 (its first term) of the inverse; one row of tiles
// likewise row 1 of M' and the term of column 1. The same expressions as
// detail::scale_offset_xy, in the same order, so every tile has the bits
// crop() gives it.
template <class T>
struct TileColumn {
    detail::Cols<T> m; // columns of M' with row 1 still to fill
    detail::V4<T> inv0, inv3_partial;
    int x0, width;
};
template <class T>
struct TileRow {
    detail::V4<T> row1; // entry j: row 1 of column j of M'
    detail::V4<T> inv1, inv3_term;
    int y0, height;
};

int tile_edge(int i, int size, int count) {
    return static_cast<int>(static_cast<long long>(i) * size / count);
}

// Column j of the column's M' with entry 1 replaced by row1[j] (no
// arithmetic, so the bits stay).
template <class T>
FRUSTUM_HOT_INLINE detail::V4<T> with_row1(const detail::V4<T>& column, const detail::V4<T>& row1, int j) {
    return detail::with_lane<1>(column, row1[j]);
}

template <class T>
struct TileMaker {
    int c, r;
    const TileColumn<T>& tc;
    const TileRow<T>& tr;
    const Vec4<T>& inv2;
    unsigned traits;
    FRUSTUM_HOT_INLINE operator Tile<T>() const { // NOLINT: implicit by design (emplace_back)
        using detail::store;
        return Tile<T>{c, r, tc.x0, tr.y0, tc.width, tr.height,
                       detail::PairFactory::keep_sign_columns<T>(
                           store<T>(with_row1<T>(tc.m.c[0], tr.row1, 0)), store<T>(with_row1<T>(tc.m.c[1], tr.row1, 1)),
                           store<T>(with_row1<T>(tc.m.c[2], tr.row1, 2)), store<T>(with_row1<T>(tc.m.c[3], tr.row1, 3)),
                           store<T>(tc.inv0), store<T>(tr.inv1), inv2, store<T>(tc.inv3_partial - tr.inv3_term), traits)};
    }
};

} // namespace

template <class T>
Result<std::vector<Tile<T>>> crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns,
                                        int rows) {
    if (width_px < 1 || height_px < 1 || columns < 1 || rows < 1 || columns > width_px || rows > height_px) {
        return detail::error<T>("crop_tiles", "need 1 <= columns <= width_px and 1 <= rows <= height_px",
                                {{"width_px", T(width_px)}, {"height_px", T(height_px)},
                                 {"columns", T(columns)}, {"rows", T(rows)}});
    }
    using detail::V4;
    const detail::Cols<T> m = detail::load(pair.matrix());
    const detail::Cols<T> inv = detail::load(pair.inverse());
    // Batched (issue 14): the per-axis crop maps are computed once per
    // column and once per row of tiles; a tile only assembles its columns
    // (four lane inserts and one subtraction) and is written in place.
    std::vector<TileColumn<T>> tile_columns(static_cast<std::size_t>(columns));
    for (int c = 0; c < columns; ++c) {
        const int x0 = tile_edge(c, width_px, columns), x1 = tile_edge(c + 1, width_px, columns);
        const CropMap<T> map = crop_map(CropRect<T>{T(x0), T(0), T(x1 - x0), T(1), T(width_px), T(1)});
        const T inv_sx = T(1) / map.sx;
        // scale_offset_xy's column with sy = 1, ty = 0: rows 2 and 3 are
        // M_j.z * 1 + M_j.w * 0 and M_j.w * 1 + M_j.w * 0, as crop() forms them.
        const V4<T> scale{map.sx, T(0), T(1), T(1)};
        const V4<T> offset{map.tx, T(0), T(0), T(0)};
        TileColumn<T>& out = tile_columns[static_cast<std::size_t>(c)];
        for (int j = 0; j < 4; ++j) {
            out.m.c[j] = m.c[j] * scale + detail::lane<3>(m.c[j]) * offset;
        }
        out.inv0 = inv.c[0] * inv_sx;
        out.inv3_partial = inv.c[3] - (map.tx * inv_sx) * inv.c[0];
        out.x0 = x0;
        out.width = x1 - x0;
    }
    std::vector<TileRow<T>> tile_rows(static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r) {
        const int y0 = tile_edge(r, height_px, rows), y1 = tile_edge(r + 1, height_px, rows);
        const CropMap<T> map = crop_map(CropRect<T>{T(0), T(y0), T(1), T(y1 - y0), T(1), T(height_px)});
        const T inv_sy = T(1) / map.sy;
        TileRow<T>& out = tile_rows[static_cast<std::size_t>(r)];
        // Built whole: a lane of a vector extension is not assignable in clang.
        const auto row1_of = [&](int j) { return m.c[j][1] * map.sy + m.c[j][3] * map.ty; };
        out.row1 = V4<T>{row1_of(0), row1_of(1), row1_of(2), row1_of(3)};
        out.inv1 = inv.c[1] * inv_sy;
        out.inv3_term = (map.ty * inv_sy) * inv.c[1];
        out.y0 = y0;
        out.height = y1 - y0;
    }
    const Vec4<T> inv2 = pair.inverse()[2];
    const unsigned traits = detail::PairFactory::traits(pair);

    std::vector<Tile<T>> tiles;
    tiles.reserve(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r) {
        const TileRow<T>& tr = tile_rows[static_cast<std::size_t>(r)];
        for (int c = 0; c < columns; ++c) {
            const TileColumn<T>& tc = tile_columns[static_cast<std::size_t>(c)];
            // emplace_back of a converter: the Tile is the prvalue its
            // conversion returns, so it is built straight in the vector's
            // storage (no temporary Tile copied in).
            tiles.emplace_back(TileMaker<T>{c, r, tc, tr, inv2, traits});
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
