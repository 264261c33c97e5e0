#include "frustum/lens.hpp"

#include "frustum/detail/depth_planes.hpp"
#include "frustum/detail/errors.hpp"
#include "frustum/detail/lens_matrices.hpp"
#include "frustum/detail/lens_tile_assembly.hpp"
#include "frustum/detail/pair_factory.hpp"
#include "frustum/detail/tile_grid_writer.hpp"
#include "frustum/from_planes.hpp"
#include "frustum/projection.hpp"
#include "frustum/queries.hpp"

#include <cmath>
#include <limits>

namespace frustum {

template <class T>
Vec2<T> lens_warp(const Vec2<T>& point_m, const Lens<T>& lens) {
    const Vec2<T> v = point_m - lens.center_m; // eq. 34: v_i = C C_i
    const T length = glm::length(v);
    if (length == T(0)) {
        return lens.center_m;
    }
    const T r = length / lens.radius_m;                                 // r_i = |v_i| / R
    return lens.center_m + (lens.radius_m * std::pow(r, lens.power) / length) * v; // C + R r^p v / |v|
}

namespace {

// Every tile of the grid, handed to `finish(index, column, row, input,
// shared)` (false: the tile is degenerate) after what neighbouring tiles
// share is built once per grid line and corner: each warped corner (eq. 34,
// a pow), its in-plane coordinates, and each edge as a 3D vector from the
// in-plane differences (detail/lens_tile_assembly.hpp builds the tile from
// them). `out` gets the crop_tiles() layout. Everything is relative to the
// eye; the tiles are moved back to the world by detail::lens_tile_store_*
// (built in world coordinates, a camera 5 km from the origin gave side
// planes whose w parts are 5000 times their normals).
template <bool with_normals, class T, class Finish>
Status lens_grid(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px, int height_px, int columns,
                 int rows, TileGrid<T>& out, Finish&& finish) {
    using detail::V4;
    if (!(lens.radius_m > T(0)) || !(lens.power > T(0)) || !std::isfinite(lens.radius_m) ||
        !std::isfinite(lens.power) || !std::isfinite(lens.center_m.x) || !std::isfinite(lens.center_m.y)) {
        detail::TileGridWriter::clear(out);
        return detail::error<T>("lens_tiles", "lens needs a finite centre, radius > 0 and power > 0",
                                {{"center_x", lens.center_m.x}, {"center_y", lens.center_m.y},
                                 {"radius", lens.radius_m}, {"power", lens.power}});
    }
    if (!(width_px >= 1 && height_px >= 1 && columns >= 1 && rows >= 1 && columns <= width_px &&
          rows <= height_px)) {
        return crop_tiles(camera, width_px, height_px, columns, rows, out); // its refusal and text
    }
    const auto failed = [&out](Error error) {
        detail::TileGridWriter::clear(out);
        return error;
    };
    auto frame_result = near_plane_frame(camera);
    if (!frame_result) {
        return failed(frame_result.take_error_in("frustum::lens_tiles()"));
    }
    const NearPlaneFrame<T>* frame = &*frame_result; // checked once
    // How much farther the far plane is than the near plane, seen from the
    // eye: |F(eye)| / |F.xyz| over |N(eye)| / |N.xyz| (raw planes, no
    // normalization of the other four).
    const detail::DepthPlanes<T> camera_planes = detail::raw_depth_planes(camera);
    if (!camera_planes.far) {
        return failed(detail::error_text("lens_tiles", "needs a finite far plane", ""));
    }
    const T far_ratio = (std::abs(camera_planes.far->distance(frame->eye)) * glm::length(camera_planes.near.normal())) /
                        (std::abs(camera_planes.near.distance(frame->eye)) * glm::length(camera_planes.far->normal()));
    // The near-plane centre relative to the eye (far from the origin
    // center - eye loses nothing: nearby floats subtract exactly), and the
    // refraction plane as the plane of the frame's axes through it: the
    // corners center + u x_axis + v y_axis lie on it to rounding, so the
    // depth row beta N vanishes on the inverse's columns c0, c1 as it must
    // (the camera's own near plane is tilted against the frame by its
    // rounding, 1e-6 in float: |M M^-1 - I| of 4e-6 in row 2).
    const Vec3<T> center = frame->center - frame->eye;
    Vec3<T> normal = glm::normalize(glm::cross(frame->x_axis, frame->y_axis));
    if (glm::dot(normal, center) < T(0)) {
        normal = -normal; // inward: away from the eye
    }
    const T near_m = glm::dot(normal, center);
    const T span = clip_z_span<T>(camera.depth());
    // beta = (z_f - z_n) r / (r - 1) (lens_tile_assembly.hpp); r - 1 must be
    // clearly positive (from_planes refuses far points closer than
    // sqrt(epsilon) of their depth to the near plane).
    if (!((far_ratio - T(1)) > std::sqrt(std::numeric_limits<T>::epsilon()) * far_ratio) ||
        !std::isfinite(far_ratio)) {
        return failed(detail::error<T>("lens_tiles", "needs a far plane clearly beyond the near plane",
                                       {{"far_over_near", far_ratio}}));
    }
    const T beta = span * far_ratio / (far_ratio - T(1));
    detail::LensTileShared<T> shared;
    shared.eye = detail::load(Vec4<T>(frame->eye, T(0)));
    shared.z_near = clip_z_near<T>(camera.depth());
    shared.inv_near_m = T(1) / near_m;
    shared.lambda = T(-1) / (beta * near_m);
    shared.far_row = beta * detail::load(Vec4<T>(normal, -near_m));
    shared.orientation = near_m / glm::dot(center, glm::cross(frame->x_axis, frame->y_axis));
    detail::TileGridWriter::layout(out, width_px, height_px, columns, rows,
                                   detail::PairFactory::traits(detail::PairFactory::keep_sign(
                                       Mat4<T>(T(1)), Mat4<T>(T(1)), camera.depth(), false)));

    // eq. 34 as X' = C + v r^(p - 1), r^(p - 1) = (|v|^2 / R^2)^((p - 1) / 2):
    // lens_warp's point without its square root and division.
    const T inv_radius2 = T(1) / (lens.radius_m * lens.radius_m);
    const T exponent = (lens.power - T(1)) / T(2);
    const Vec2<T> half(frame->half_width_m, frame->half_height_m);
    const std::size_t n = static_cast<std::size_t>(columns) + 1;
    // Scratch kept with the grid: corners (X, 1) and in-plane (u, v) of the
    // bottom and top lines of the row of tiles being built, the edges along
    // those two lines and the vertical edges of the row, the columns' x on
    // the near plane before eq. 34; with_normals: the edges' planes through
    // the eye too (X_from x X_to = X_from x edge).
    Vec4<T>* scratch = detail::TileGridWriter::scratch(out, (with_normals ? 11 : 8) * n);
    Vec4<T>* corners = scratch;
    Vec4<T>* plane = scratch + 2 * n;
    Vec4<T>* horizontal = scratch + 4 * n;
    Vec4<T>* vertical = scratch + 6 * n;
    Vec4<T>* column_x = scratch + 7 * n;
    Vec4<T>* horizontal_normal = scratch + 8 * n;
    Vec4<T>* vertical_normal = scratch + 10 * n;
    for (int c = 0; c <= columns; ++c) {
        column_x[c].x = (T(-1) + T(2) * T(out.x_px(c)) / T(width_px)) * half.x;
    }
    const auto normal_of = [](const Vec4<T>& from, const Vec4<T>& along) {
        return Vec4<T>(glm::cross(Vec3<T>(from), Vec3<T>(along)), T(0));
    };
    const detail::V4<T> x_axis = detail::load(Vec4<T>(frame->x_axis, T(0)));
    const detail::V4<T> y_axis = detail::load(Vec4<T>(frame->y_axis, T(0)));
    const detail::V4<T> center_w = detail::load(Vec4<T>(center, T(1)));
    const auto corner_line = [&](int r, std::size_t half_index) {
        const T y_m = (T(-1) + T(2) * T(out.y_px(r)) / T(height_px)) * half.y - lens.center_m.y;
        for (int c = 0; c <= columns; ++c) {
            const std::size_t k = half_index * n + static_cast<std::size_t>(c);
            const T v_x = column_x[c].x - lens.center_m.x;
            const T length2 = v_x * v_x + y_m * y_m;
            const T scaled = length2 * inv_radius2;
            // r^(p - 1) = scaled^((p - 1) / 2); p = 2 (the sample app's lens) is a square root.
            const T factor = length2 == T(0) ? T(0) : exponent == T(0.5) ? std::sqrt(scaled) : std::pow(scaled, exponent);
            const T u = lens.center_m.x + factor * v_x, w = lens.center_m.y + factor * y_m;
            plane[k] = Vec4<T>(u, w, T(0), T(0));
            corners[k] = detail::store<T>(center_w + x_axis * u + y_axis * w);
            if (c > 0) { // X_this - X_left
                horizontal[k - 1] = detail::store<T>(x_axis * (u - plane[k - 1].x) + y_axis * (w - plane[k - 1].y));
                if constexpr (with_normals) {
                    horizontal_normal[k - 1] = normal_of(corners[k - 1], horizontal[k - 1]);
                }
            }
        }
    };
    corner_line(0, 0);
    for (int r = 0; r < rows; ++r) {
        const std::size_t lo = static_cast<std::size_t>(r % 2) * n, hi = n - lo; // bottom, top lines
        corner_line(r + 1, hi / n);
        for (std::size_t c = 0; c < n; ++c) { // X_top - X_bottom
            vertical[c] = detail::store<T>(x_axis * (plane[hi + c].x - plane[lo + c].x) +
                                           y_axis * (plane[hi + c].y - plane[lo + c].y));
            if constexpr (with_normals) {
                vertical_normal[c] = normal_of(corners[lo + c], vertical[c]);
            }
        }
        for (int c = 0; c < columns; ++c) {
            const std::size_t k = static_cast<std::size_t>(c);
            detail::LensTileInput<T> in;
            in.corners[0] = corners + lo + k; // bl, br, tr, tl
            in.corners[1] = corners + lo + k + 1;
            in.corners[2] = corners + hi + k + 1;
            in.corners[3] = corners + hi + k;
            in.plane[0] = plane + lo + k;
            in.plane[1] = plane + lo + k + 1;
            in.plane[2] = plane + hi + k + 1;
            in.plane[3] = plane + hi + k;
            in.bottom = horizontal + lo + k;
            in.top = horizontal + hi + k;
            in.left = vertical + k;
            in.right = vertical + k + 1;
            if constexpr (with_normals) {
                in.normals[0] = vertical_normal + k;          // X_0 x X_3
                in.normals[1] = vertical_normal + k + 1;      // X_1 x X_2
                in.normals[2] = horizontal_normal + lo + k;   // X_0 x X_1
                in.normals[3] = horizontal_normal + hi + k;   // X_3 x X_2
            }
            if (!finish(out.index(c, r), in, shared)) {
                return failed(detail::error_text(
                    "lens_tiles", "a tile's lens frustum is degenerate",
                    "tile (" + detail::number(c) + ", " + detail::number(r) +
                        "): its moved corners are not a convex quad of one orientation"));
            }
        }
    }
    return {};
}

} // namespace

template <class T>
Status lens_tiles(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px, int height_px, int columns,
                  int rows, TileGrid<T>& out) {
    using detail::TileGridWriter;
    Mat4<T>* matrices = nullptr;
    Mat4<T>* inverses = nullptr;
    return lens_grid<false>(camera, lens, width_px, height_px, columns, rows, out,
                     [&](std::size_t i, const detail::LensTileInput<T>& in,
                         const detail::LensTileShared<T>& shared) FRUSTUM_LENS_INLINE {
                         detail::V4<T> columns_relative[4];
                         detail::Cols<T> rows_relative;
                         if (!detail::lens_tile_inverse(in, shared, columns_relative) ||
                             !detail::lens_tile_rows(columns_relative, shared, rows_relative)) {
                             return false;
                         }
                         if (matrices == nullptr) {
                             matrices = TileGridWriter::matrices(out);
                             inverses = TileGridWriter::inverses(out);
                         }
                         detail::lens_tile_store_matrix(rows_relative, shared, matrices[i]);
                         detail::lens_tile_store_inverse(columns_relative, shared, inverses[i]);
                         return true;
                     });
}

template <class T>
Result<std::vector<Tile<T>>> lens_tiles(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px,
                                        int height_px, int columns, int rows) {
    TileGrid<T> grid;
    if (Status status = lens_tiles(camera, lens, width_px, height_px, columns, rows, grid); !status) {
        return status.take_error();
    }
    return detail::tiles_of(grid);
}

namespace detail {

// The baseline's matrix: the same tile's M assembled from its edge planes
// alone (lens_tile_rows_from_planes), the cheapest forward form, for "build
// the matrix, then invert it".
template <class T>
Status lens_tile_matrices(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px, int height_px,
                          int columns, int rows, TileGrid<T>& layout, std::vector<Mat4<T>>& matrices) {
    matrices.resize(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
    return lens_grid<true>(camera, lens, width_px, height_px, columns, rows, layout,
                     [&](std::size_t i, const LensTileInput<T>& in, const LensTileShared<T>& shared) FRUSTUM_LENS_INLINE {
                         Cols<T> rows_relative;
                         if (!lens_tile_rows_from_planes(in, shared, rows_relative)) {
                             return false;
                         }
                         lens_tile_store_matrix(rows_relative, shared, matrices[i]);
                         return true;
                     });
}

} // namespace detail

#define FRUSTUM_INSTANTIATE(T)                                                                             \
    template Vec2<T> lens_warp(const Vec2<T>&, const Lens<T>&);                                            \
    template Result<std::vector<Tile<T>>> lens_tiles(const MatrixPair<T>&, const Lens<T>&, int, int, int, int); \
    template Status lens_tiles(const MatrixPair<T>&, const Lens<T>&, int, int, int, int, TileGrid<T>&);         \
    template Status detail::lens_tile_matrices(const MatrixPair<T>&, const Lens<T>&, int, int, int, int,       \
                                               TileGrid<T>&, std::vector<Mat4<T>>&);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
