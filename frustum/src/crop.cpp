#include "frustum/crop.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/pair_updates.hpp"
#include "frustum/detail/tile_grid_writer.hpp"

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

template <class T>
MatrixPair<T> TileGrid<T>::pair(std::size_t i) const {
    const Mat4<T>& m = matrices_[i];
    const Mat4<T>& inv = inverses_[i];
    return detail::PairFactory::keep_sign_columns<T>(m[0], m[1], m[2], m[3], inv[0], inv[1], inv[2], inv[3],
                                                     traits_);
}

template <class T>
Tile<T> TileGrid<T>::tile(std::size_t i) const {
    const int column = static_cast<int>(i % static_cast<std::size_t>(columns_));
    const int row = static_cast<int>(i / static_cast<std::size_t>(columns_));
    return Tile<T>{column, row, x_px(column), y_px(row), width_px(column), height_px(row), pair(i)};
}

// Batched (issue 14). The crop map of a tile is the x map of its column and
// the y map of its row, so each is computed once per column and once per
// row of tiles, with the expressions of detail::scale_offset_xy in its
// order: every tile gets the bits crop() gives it. A column of tiles holds
// rows 0, 2 and 3 of every column of M' (row 1 still open), column 0 of the
// inverse and the first term of column 3; a row of tiles holds row 1 of M',
// column 1 of the inverse and the second term of column 3. Per tile: four
// lane inserts, one subtraction and eight whole-column stores.
template <class T>
Status crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns, int rows,
                  TileGrid<T>& out) {
    using detail::TileGridWriter;
    using detail::V4;
    if (width_px < 1 || height_px < 1 || columns < 1 || rows < 1 || columns > width_px || rows > height_px) {
        TileGridWriter::clear(out);
        return detail::error<T>("crop_tiles", "need 1 <= columns <= width_px and 1 <= rows <= height_px",
                                {{"width_px", T(width_px)}, {"height_px", T(height_px)},
                                 {"columns", T(columns)}, {"rows", T(rows)}});
    }
    TileGridWriter::layout(out, width_px, height_px, columns, rows, detail::PairFactory::traits(pair));
    const detail::Cols<T> m = detail::load(pair.matrix());
    const detail::Cols<T> inv = detail::load(pair.inverse());

    // Per column of tiles, six vectors: columns 0-3 of M' with row 1 open,
    // inverse column 0, and inverse column 3 less its row term.
    constexpr std::size_t kParts = 6;
    Vec4<T>* parts = TileGridWriter::scratch(out, kParts * static_cast<std::size_t>(columns));
    for (int c = 0; c < columns; ++c) {
        const int x0 = out.x_px(c), x1 = out.x_px(c + 1);
        const CropMap<T> map = crop_map(CropRect<T>{T(x0), T(0), T(x1 - x0), T(1), T(width_px), T(1)});
        const T inv_sx = T(1) / map.sx;
        // scale_offset_xy's column with sy = 1, ty = 0: rows 2 and 3 are
        // M_j.z * 1 + M_j.w * 0 and M_j.w * 1 + M_j.w * 0, as crop() forms them.
        const V4<T> scale{map.sx, T(0), T(1), T(1)};
        const V4<T> offset{map.tx, T(0), T(0), T(0)};
        Vec4<T>* part = parts + kParts * static_cast<std::size_t>(c);
        for (int j = 0; j < 4; ++j) {
            part[j] = detail::store<T>(m.c[j] * scale + detail::lane<3>(m.c[j]) * offset);
        }
        part[4] = detail::store<T>(inv.c[0] * inv_sx);
        part[5] = detail::store<T>(inv.c[3] - (map.tx * inv_sx) * inv.c[0]);
    }
    const V4<T> inv2 = inv.c[2];
    Mat4<T>* matrices = TileGridWriter::matrices(out);
    Mat4<T>* inverses = TileGridWriter::inverses(out);
    for (int r = 0; r < rows; ++r) {
        const int y0 = out.y_px(r), y1 = out.y_px(r + 1);
        const CropMap<T> map = crop_map(CropRect<T>{T(0), T(y0), T(1), T(y1 - y0), T(1), T(height_px)});
        const T inv_sy = T(1) / map.sy;
        const T row1_0 = m.c[0][1] * map.sy + m.c[0][3] * map.ty;
        const T row1_1 = m.c[1][1] * map.sy + m.c[1][3] * map.ty;
        const T row1_2 = m.c[2][1] * map.sy + m.c[2][3] * map.ty;
        const T row1_3 = m.c[3][1] * map.sy + m.c[3][3] * map.ty;
        const V4<T> inv1 = inv.c[1] * inv_sy;
        const V4<T> inv3_term = (map.ty * inv_sy) * inv.c[1];
        const std::size_t first = out.index(0, r);
        for (int c = 0; c < columns; ++c) {
            const Vec4<T>* part = parts + kParts * static_cast<std::size_t>(c);
            const std::size_t i = first + static_cast<std::size_t>(c);
            // Entry 1 of each column replaced (no arithmetic, so the bits stay).
            detail::store_columns<T>(matrices[i], detail::with_lane<1>(detail::load(part[0]), row1_0),
                                     detail::with_lane<1>(detail::load(part[1]), row1_1),
                                     detail::with_lane<1>(detail::load(part[2]), row1_2),
                                     detail::with_lane<1>(detail::load(part[3]), row1_3));
            detail::store_columns<T>(inverses[i], detail::load(part[4]), inv1, inv2,
                                     detail::load(part[5]) - inv3_term);
        }
    }
    return {};
}

template <class T>
Result<std::vector<Tile<T>>> crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns,
                                        int rows) {
    TileGrid<T> grid;
    if (Status status = crop_tiles(pair, width_px, height_px, columns, rows, grid); !status) {
        return status.take_error();
    }
    return detail::tiles_of(grid);
}

#define FRUSTUM_INSTANTIATE(T)                                                                   \
    template Result<MatrixPair<T>> crop(const MatrixPair<T>&, const CropRect<T>&);               \
    template Result<MatrixPair<T>> uncrop(const MatrixPair<T>&, const CropRect<T>&);             \
    template Result<std::vector<Tile<T>>> crop_tiles(const MatrixPair<T>&, int, int, int, int);         \
    template Status crop_tiles(const MatrixPair<T>&, int, int, int, int, TileGrid<T>&);                \
    template class TileGrid<T>;
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
