#include "frustum/lens.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/from_planes_points.hpp"
#include "frustum/detail/lens_matrices.hpp"
#include "frustum/detail/pair_factory.hpp"
#include "frustum/detail/tile_grid_writer.hpp"
#include "frustum/from_planes.hpp"
#include "frustum/projection.hpp"
#include "frustum/queries.hpp"

#include <cmath>

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

// The plane through the eye (the origin, lens_grid works relative to it)
// and two points, unit normal (a tile faces it inward with facing()).
template <class T>
Plane<T> edge_plane(const Vec3<T>& a, const Vec3<T>& b) {
    return Plane<T>::at(glm::normalize(glm::cross(a, b)), Vec3<T>(T(0)));
}

// World to eye-relative coordinates, T(-eye): a tile built relative to the
// eye is compose(tile, world_to_eye(eye)), i.e. M T(-eye) and T(eye) M^-1
// (analytic).
template <class T>
RigidTransform<T> world_to_eye(const Vec3<T>& eye) {
    return RigidTransform<T>::from_rotation_translation(Mat3<T>(T(1)), -eye);
}

// The planes and far points of every tile, built once per grid line and
// corner and handed to `finish(index, column, row, sides, far_points,
// to_eye)` tile by tile. Shared corners and edge planes are the same
// expressions a tile on its own would evaluate (lens_warp of the same
// pixel, the same cross product and normalization; facing() per tile), so
// the bits are those of building each tile alone. `out` gets the
// crop_tiles() layout.
//
// Everything is relative to the eye (the eye at the origin: side planes
// through it have d = 0); `finish` moves the tile back to the world with
// to_eye = world_to_eye(eye). Built in world coordinates, a camera 5 km
// from the origin gave side rows whose w parts are 5000 times their
// normals, and from_planes refused them as dependent.
template <class T, class Finish>
Status lens_grid(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px, int height_px, int columns,
                 int rows, TileGrid<T>& out, Finish&& finish) {
    if (!(lens.radius_m > T(0)) || !(lens.power > T(0)) || !std::isfinite(lens.radius_m) ||
        !std::isfinite(lens.power) || !std::isfinite(lens.center_m.x) || !std::isfinite(lens.center_m.y)) {
        detail::TileGridWriter::clear(out);
        return detail::error<T>("lens_tiles", "lens needs a finite centre, radius > 0 and power > 0",
                                {{"center_x", lens.center_m.x}, {"center_y", lens.center_m.y},
                                 {"radius", lens.radius_m}, {"power", lens.power}});
    }
    if (Status layout = crop_tiles(camera, width_px, height_px, columns, rows, out); !layout) {
        return layout;
    }
    const auto failed = [&out](Error error) {
        detail::TileGridWriter::clear(out);
        return error;
    };
    const auto frame = near_plane_frame(camera);
    if (!frame) {
        return failed(frame.take_error_in("frustum::lens_tiles()"));
    }
    const auto camera_planes = planes(camera);
    if (!camera_planes.far) {
        return failed(detail::error_text("lens_tiles", "needs a finite far plane", ""));
    }
    // How much farther the far plane is than the near plane, seen from the eye.
    const T far_ratio = std::abs(camera_planes.far->distance(frame->eye)) /
                        std::abs(camera_planes.near.distance(frame->eye));
    // The near-plane frame and near plane relative to the eye (far from the
    // origin center - eye loses nothing: nearby floats subtract exactly).
    NearPlaneFrame<T> relative = *frame;
    relative.center = frame->center - frame->eye;
    relative.eye = Vec3<T>(T(0));
    const RigidTransform<T> to_eye = world_to_eye(frame->eye);
    const Plane<T> near_plane = Plane<T>::at(camera_planes.near.normal(), relative.center);

    // A moved point of the refraction plane for the pixel position (x, y).
    const auto moved = [&](int x_px, int y_px) {
        const Vec2<T> ndc(T(-1) + T(2) * T(x_px) / T(width_px), T(-1) + T(2) * T(y_px) / T(height_px));
        const Vec2<T> plane_m(ndc.x * frame->half_width_m, ndc.y * frame->half_height_m);
        return relative.point(lens_warp(plane_m, lens));
    };
    const auto far_point = [&](const Vec3<T>& corner) { return corner * far_ratio; };
    const std::size_t n = static_cast<std::size_t>(columns) + 1;
    // Corners, far points and the planes along the bottom edges of the row
    // of tiles being built (index r) and of the one above (r + 1).
    std::vector<Vec3<T>> corners(2 * n), far_points(2 * n);
    std::vector<Plane<T>> horizontal(2 * n), vertical(n);
    const auto corner_row = [&](int r, std::size_t half) {
        for (int c = 0; c <= columns; ++c) {
            const std::size_t k = half * n + static_cast<std::size_t>(c);
            corners[k] = moved(out.x_px(c), out.y_px(r));
            far_points[k] = far_point(corners[k]);
            if (c > 0) { // the plane through this corner and the one to its left
                horizontal[k - 1] = edge_plane(corners[k - 1], corners[k]);
            }
        }
    };
    corner_row(0, 0);
    for (int r = 0; r < rows; ++r) {
        const std::size_t lo = static_cast<std::size_t>(r % 2) * n, hi = n - lo; // bottom, top halves
        corner_row(r + 1, hi / n);
        for (std::size_t c = 0; c < n; ++c) {
            vertical[c] = edge_plane(corners[lo + c], corners[hi + c]);
        }
        for (int c = 0; c < columns; ++c) {
            const std::size_t k = static_cast<std::size_t>(c);
            const Vec3<T>& bottom_left = corners[lo + k];
            const Vec3<T>& bottom_right = corners[lo + k + 1];
            const Vec3<T>& top_right = corners[hi + k + 1];
            const Vec3<T>& top_left = corners[hi + k];
            const Vec3<T> inside = (bottom_left + bottom_right + top_right + top_left) / T(4);
            const SidePlanes<T> sides{vertical[k].facing(inside), vertical[k + 1].facing(inside),
                                      horizontal[lo + k].facing(inside), horizontal[hi + k].facing(inside),
                                      near_plane};
            // The far plane keeps each moved corner's ray inside up to the
            // camera's far distance (one far point would tilt it into the tile).
            const Vec3<T> tile_far[4] = {far_points[lo + k], far_points[lo + k + 1], far_points[hi + k + 1],
                                         far_points[hi + k]};
            if (Status status = finish(out.index(c, r), c, r, sides, tile_far, to_eye); !status) {
                return failed(status.take_error());
            }
        }
    }
    return {};
}

// A tile's lens frustum failed: the error names the tile.
Error tile_error(int column, int row, const std::string& error) {
    return detail::error_text("lens_tiles", "a tile's lens frustum is degenerate",
                              "tile (" + detail::number(column) + ", " + detail::number(row) + "): " + error);
}

} // namespace

template <class T>
Status lens_tiles(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px, int height_px, int columns,
                  int rows, TileGrid<T>& out) {
    using detail::TileGridWriter;
    return lens_grid(camera, lens, width_px, height_px, columns, rows, out,
                     [&](std::size_t i, int c, int r, const SidePlanes<T>& sides, const Vec3<T>* far,
                         const RigidTransform<T>& to_eye) -> Status {
                         auto relative = detail::from_planes_points(sides, far, 4, camera.depth());
                         if (!relative) {
                             return tile_error(c, r, relative.error());
                         }
                         const MatrixPair<T> pair = compose(*relative, to_eye);
                         TileGridWriter::matrices(out)[i] = pair.matrix();
                         TileGridWriter::inverses(out)[i] = pair.inverse();
                         TileGridWriter::set_traits(out, detail::PairFactory::traits(pair));
                         return {};
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

template <class T>
Status lens_tile_matrices(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px, int height_px,
                          int columns, int rows, TileGrid<T>& layout, std::vector<Mat4<T>>& matrices) {
    matrices.resize(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
    return lens_grid(camera, lens, width_px, height_px, columns, rows, layout,
                     [&](std::size_t i, int c, int r, const SidePlanes<T>& sides, const Vec3<T>* far,
                         const RigidTransform<T>& to_eye) -> Status {
                         auto m = from_planes_matrix(sides, far, 4, camera.depth());
                         if (!m) {
                             return tile_error(c, r, m.error());
                         }
                         matrices[i] = *m * to_eye.matrix;
                         return {};
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
