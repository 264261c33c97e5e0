#include "frustum/crop.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/pair_factory.hpp"

#include <cmath>

namespace frustum {

namespace {

// The clip-space map x' = sx x + tx w, y' = sy y + ty w applied to a pair:
// rows 0 and 1 of M pick up row 3; the inverse undoes it column-wise.
template <class T>
MatrixPair<T> scale_offset_xy(const MatrixPair<T>& pair, T sx, T tx, T sy, T ty) {
    // Row-wise m0' = sx m0 + tx m3, m1' = sy m1 + ty m3, done column by
    // column (GLM is column-major: whole-column arithmetic vectorizes and
    // avoids scattered stores).
    const Vec4<T> scale(sx, sy, T(1), T(1));
    const Vec4<T> offset(tx, ty, T(0), T(0));
    Mat4<T> m;
    for (int j = 0; j < 4; ++j) {
        m[j] = pair.matrix()[j] * scale + pair.matrix()[j].w * offset;
    }
    const T inv_sx = T(1) / sx, inv_sy = T(1) / sy;
    Mat4<T> inv = pair.inverse();
    inv[0] = pair.inverse()[0] * inv_sx;
    inv[1] = pair.inverse()[1] * inv_sy;
    inv[3] = pair.inverse()[3] - (tx * inv_sx) * pair.inverse()[0] - (ty * inv_sy) * pair.inverse()[1];
    return detail::PairFactory::keep_sign(m, inv, pair.depth(), pair.flips_winding());
}

template <class T>
bool rect_is_valid(const CropRect<T>& r) {
    // Every comparison is false for NaN; infinities fail the size bounds.
    return std::isfinite(r.full_width) && std::isfinite(r.full_height) && r.full_width > T(0) &&
           r.full_height > T(0) && r.width > T(0) && r.height > T(0) && r.x >= T(0) && r.y >= T(0) &&
           r.x + r.width <= r.full_width && r.y + r.height <= r.full_height;
}

template <class T>
Error rect_error(const CropRect<T>& r, const char* function) {
    const bool sizes_ok = r.full_width > T(0) && r.full_height > T(0) && r.width > T(0) && r.height > T(0);
    const bool finite = std::isfinite(r.x) && std::isfinite(r.y) && std::isfinite(r.width) &&
                        std::isfinite(r.height) && std::isfinite(r.full_width) && std::isfinite(r.full_height);
    return detail::error<T>(function,
                            !finite     ? "crop rectangle must be finite"
                            : !sizes_ok ? "crop and image sizes must be > 0"
                                        : "crop rectangle must lie inside the image",
                            {{"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height},
                             {"full_width", r.full_width}, {"full_height", r.full_height}});
}

// Crop coefficients (eq. 14): x' = w x + (w - 1 - 2 X/bw) w_clip.
template <class T>
struct CropMap {
    T sx, tx, sy, ty;
};
template <class T>
CropMap<T> crop_map(const CropRect<T>& r) {
    const T inv_width = T(1) / r.width, inv_height = T(1) / r.height;
    const T w = r.full_width * inv_width;
    const T h = r.full_height * inv_height;
    return {w, w - T(1) - T(2) * r.x * inv_width, h, h - T(1) - T(2) * r.y * inv_height};
}

} // namespace

template <class T>
Result<MatrixPair<T>> crop(const MatrixPair<T>& pair, const CropRect<T>& rect) {
    if (!rect_is_valid(rect)) {
        return rect_error(rect, "crop");
    }
    const CropMap<T> c = crop_map(rect);
    return scale_offset_xy(pair, c.sx, c.tx, c.sy, c.ty);
}

template <class T>
Result<MatrixPair<T>> uncrop(const MatrixPair<T>& pair, const CropRect<T>& rect) {
    if (!rect_is_valid(rect)) {
        return rect_error(rect, "uncrop");
    }
    // invCropMat of eq. 14: x = (x' - t w) / s.
    const CropMap<T> c = crop_map(rect);
    return scale_offset_xy(pair, T(1) / c.sx, -c.tx / c.sx, T(1) / c.sy, -c.ty / c.sy);
}

template <class T>
Result<std::vector<Tile<T>>> crop_tiles(const MatrixPair<T>& pair, int width_px, int height_px, int columns,
                                        int rows) {
    if (width_px < 1 || height_px < 1 || columns < 1 || rows < 1 || columns > width_px || rows > height_px) {
        return detail::error<T>("crop_tiles", "need 1 <= columns <= width_px and 1 <= rows <= height_px",
                                {{"width_px", T(width_px)}, {"height_px", T(height_px)},
                                 {"columns", T(columns)}, {"rows", T(rows)}});
    }
    std::vector<Tile<T>> tiles;
    tiles.reserve(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
    const auto edge = [](int i, int size, int count) {
        return static_cast<int>(static_cast<long long>(i) * size / count);
    };
    for (int r = 0; r < rows; ++r) {
        const int y0 = edge(r, height_px, rows), y1 = edge(r + 1, height_px, rows);
        for (int c = 0; c < columns; ++c) {
            const int x0 = edge(c, width_px, columns), x1 = edge(c + 1, width_px, columns);
            const CropRect<T> rect{T(x0), T(y0), T(x1 - x0), T(y1 - y0), T(width_px), T(height_px)};
            const CropMap<T> m = crop_map(rect);
            tiles.push_back(Tile<T>{c, r, x0, y0, x1 - x0, y1 - y0, scale_offset_xy(pair, m.sx, m.tx, m.sy, m.ty)});
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
