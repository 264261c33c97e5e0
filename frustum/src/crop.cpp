#include "frustum/crop.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/pair_updates.hpp"
#include "frustum/detail/tile_grid_writer.hpp"

#include <cmath>
#include <cstring>
#include <type_traits>

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

namespace {

// Batched (issue 14). The crop map of a tile is the x map of its column and
// the y map of its row, so each is computed once per column and once per
// row of tiles, with the expressions of detail::scale_offset_xy in its
// order: every tile gets the bits crop() gives it. A column of tiles holds
// rows 0, 2 and 3 of every column of M' (row 1 still open), column 0 of the
// inverse and the first term of column 3 (kColumnParts vectors); a row of
// tiles holds row 1 of M', column 1 of the inverse and the factor of the
// second term of column 3. Per tile: four ORs (with_row1), one multiply and
// one subtraction, eight column stores.
constexpr std::size_t kColumnParts = 6;

template <class T>
void column_parts(const detail::Cols<T>& m, const detail::Cols<T>& inv, int x0, int x1, int width_px,
                  Vec4<T>* part) {
    using detail::V4;
    const CropMap<T> map = crop_map(CropRect<T>{T(x0), T(0), T(x1 - x0), T(1), T(width_px), T(1)});
    const T inv_sx = T(1) / map.sx;
    // scale_offset_xy's column with sy = 1, ty = 0: rows 2 and 3 are
    // M_j.z * 1 + M_j.w * 0 and M_j.w * 1 + M_j.w * 0, as crop() forms them.
    const V4<T> scale{map.sx, T(0), T(1), T(1)};
    const V4<T> offset{map.tx, T(0), T(0), T(0)};
    for (int j = 0; j < 4; ++j) { // entry 1 cleared to +0 (all bits zero) for with_row1
        part[j] = detail::store<T>(detail::with_lane<1>(m.c[j] * scale + detail::lane<3>(m.c[j]) * offset, T(0)));
    }
    part[4] = detail::store<T>(inv.c[0] * inv_sx);
    part[5] = detail::store<T>(inv.c[3] - (map.tx * inv_sx) * inv.c[0]);
}

template <class T>
struct RowParts {
    Vec4<T> row1[4]; // (0, row 1 of column j of M', 0, 0)
    Vec4<T> inv1;
    T shift; // ty / sy: inverse column 3 is (column part) - shift inv_1
};
template <class T>
RowParts<T> row_parts(const detail::Cols<T>& m, const detail::Cols<T>& inv, int y0, int y1, int height_px) {
    const CropMap<T> map = crop_map(CropRect<T>{T(0), T(y0), T(1), T(y1 - y0), T(1), T(height_px)});
    const T inv_sy = T(1) / map.sy;
    RowParts<T> out;
    for (int j = 0; j < 4; ++j) {
        out.row1[j] = Vec4<T>(T(0), m.c[j][1] * map.sy + m.c[j][3] * map.ty, T(0), T(0));
    }
    out.inv1 = detail::store<T>(inv.c[1] * inv_sy);
    out.shift = map.ty * inv_sy;
    return out;
}

// Inverse column 3 of a tile: its column's part less the row's term, the
// product formed here as crop() forms it (inv3 - a inv0 - b inv1), so a
// compiler that fuses multiply-adds (aarch64) fuses both alike.
template <class T>
FRUSTUM_HOT_INLINE Vec4<T> inverse_column3(const Vec4<T>& part, T shift, const detail::V4<T>& inv1) {
    return detail::store<T>(detail::load(part) - shift * inv1);
}

// A column part (entry 1 all bits zero) with entry 1 put in from the row's
// (0, row1, 0, 0): a bitwise OR, so every entry keeps its bits (signed
// zeros too) at one instruction, where a lane insert takes three shuffles
// on x86-64's SSE2. In double only the low half changes.
template <class T>
FRUSTUM_HOT_INLINE Vec4<T> with_row1(const Vec4<T>& column, const Vec4<T>& row1) {
    typedef unsigned long long Bits __attribute__((vector_size(16)));
    Bits a, b;
    std::memcpy(&a, &column, sizeof a);
    std::memcpy(&b, &row1, sizeof b);
    a |= b;
    Vec4<T> out;
    std::memcpy(&out, &a, sizeof a);
    if constexpr (sizeof(Vec4<T>) > sizeof(Bits)) {
        std::memcpy(&out[2], &column[2], sizeof a);
    }
    return out;
}

// The vector form's Tile (c, r), built by its conversion straight in the
// vector's storage (emplace_back; C++17 guaranteed elision).
template <class T>
struct CropTileMaker {
    int c, r, x0, y0, width, height;
    const Vec4<T>* part;
    const RowParts<T>& row;
    const Vec4<T>& inv2;
    const detail::V4<T>& inv1; // the camera's inverse column 1
    unsigned traits;
    FRUSTUM_HOT_INLINE operator Tile<T>() const { // NOLINT: implicit by design (emplace_back)
        return Tile<T>{c, r, x0, y0, width, height,
                       detail::PairFactory::keep_sign_columns<T>(
                           with_row1<T>(part[0], row.row1[0]), with_row1<T>(part[1], row.row1[1]),
                           with_row1<T>(part[2], row.row1[2]), with_row1<T>(part[3], row.row1[3]), part[4],
                           row.inv1, inv2, inverse_column3<T>(part[5], row.shift, inv1), traits)};
    }
};

template <class T>
Status tiles_refused(int width_px, int height_px, int columns, int rows) {
    return detail::error<T>("crop_tiles", "need 1 <= columns <= width_px and 1 <= rows <= height_px",
                            {{"width_px", T(width_px)}, {"height_px", T(height_px)},
                             {"columns", T(columns)}, {"rows", T(rows)}});
}
bool tiles_fit(int width_px, int height_px, int columns, int rows) {
    return width_px >= 1 && height_px >= 1 && columns >= 1 && rows >= 1 && columns <= width_px && rows <= height_px;
}

} // namespace

template <class T>
Status crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns, int rows,
                  TileGrid<T>& out) {
    using detail::TileGridWriter;
    if (!tiles_fit(width_px, height_px, columns, rows)) {
        TileGridWriter::clear(out);
        return tiles_refused<T>(width_px, height_px, columns, rows);
    }
    TileGridWriter::layout(out, width_px, height_px, columns, rows, detail::PairFactory::traits(pair));
    const detail::Cols<T> m = detail::load(pair.matrix());
    const detail::Cols<T> inv = detail::load(pair.inverse());
    Vec4<T>* parts = TileGridWriter::scratch(out, kColumnParts * static_cast<std::size_t>(columns));
    for (int c = 0; c < columns; ++c) {
        column_parts(m, inv, out.x_px(c), out.x_px(c + 1), width_px, parts + kColumnParts * static_cast<std::size_t>(c));
    }
    const Vec4<T> inv2 = pair.inverse()[2];
    Mat4<T>* matrices = TileGridWriter::matrices(out);
    Mat4<T>* inverses = TileGridWriter::inverses(out);
    for (int r = 0; r < rows; ++r) {
        const RowParts<T> row = row_parts(m, inv, out.y_px(r), out.y_px(r + 1), height_px);
        const std::size_t first = out.index(0, r);
        for (int c = 0; c < columns; ++c) {
            const Vec4<T>* part = parts + kColumnParts * static_cast<std::size_t>(c);
            Mat4<T>& mo = matrices[first + static_cast<std::size_t>(c)];
            Mat4<T>& io = inverses[first + static_cast<std::size_t>(c)];
            mo[0] = with_row1<T>(part[0], row.row1[0]);
            mo[1] = with_row1<T>(part[1], row.row1[1]);
            mo[2] = with_row1<T>(part[2], row.row1[2]);
            mo[3] = with_row1<T>(part[3], row.row1[3]);
            io[0] = part[4];
            io[1] = row.inv1;
            io[2] = inv2;
            io[3] = inverse_column3<T>(part[5], row.shift, inv.c[1]);
        }
    }
    return {};
}

template <class T>
Result<std::vector<Tile<T>>> crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns,
                                        int rows) {
    if (!tiles_fit(width_px, height_px, columns, rows)) {
        return tiles_refused<T>(width_px, height_px, columns, rows).take_error();
    }
    const detail::Cols<T> m = detail::load(pair.matrix());
    const detail::Cols<T> inv = detail::load(pair.inverse());
    std::vector<Vec4<T>> parts(kColumnParts * static_cast<std::size_t>(columns));
    std::vector<int> x_edges(static_cast<std::size_t>(columns) + 1); // once, not per tile
    std::vector<int> y_edges(static_cast<std::size_t>(rows) + 1);
    detail::tile_edges(width_px, columns, x_edges.data());
    detail::tile_edges(height_px, rows, y_edges.data());
    for (int c = 0; c < columns; ++c) {
        column_parts(m, inv, x_edges[static_cast<std::size_t>(c)], x_edges[static_cast<std::size_t>(c) + 1],
                     width_px, &parts[kColumnParts * static_cast<std::size_t>(c)]);
    }
    const Vec4<T> inv2 = pair.inverse()[2];
    const unsigned traits = detail::PairFactory::traits(pair);
    std::vector<Tile<T>> tiles;
    tiles.reserve(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r) {
        const int y0 = y_edges[static_cast<std::size_t>(r)], y1 = y_edges[static_cast<std::size_t>(r) + 1];
        const RowParts<T> row = row_parts(m, inv, y0, y1, height_px);
        for (int c = 0; c < columns; ++c) {
            const int x0 = x_edges[static_cast<std::size_t>(c)], x1 = x_edges[static_cast<std::size_t>(c) + 1];
            tiles.emplace_back(CropTileMaker<T>{c, r, x0, y0, x1 - x0, y1 - y0,
                                                &parts[kColumnParts * static_cast<std::size_t>(c)], row, inv2,
                                                inv.c[1], traits});
        }
    }
    return tiles;
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
