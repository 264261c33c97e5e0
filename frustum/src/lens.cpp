#include "frustum/lens.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/from_planes.hpp"
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

// The plane through the eye and two points, unit normal, positive on the side of `inside`.
template <class T>
Plane<T> side_plane(const Vec3<T>& eye, const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& inside) {
    return Plane<T>::at(glm::normalize(glm::cross(a - eye, b - eye)), eye).facing(inside);
}

} // namespace

template <class T>
Result<std::vector<Tile<T>>> lens_tiles(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px,
                                        int height_px, int columns, int rows) {
    if (!(lens.radius_m > T(0)) || !(lens.power > T(0)) || !std::isfinite(lens.radius_m) ||
        !std::isfinite(lens.power) || !std::isfinite(lens.center_m.x) || !std::isfinite(lens.center_m.y)) {
        return detail::error<T>("lens_tiles", "lens needs a finite centre, radius > 0 and power > 0",
                                {{"center_x", lens.center_m.x}, {"center_y", lens.center_m.y},
                                 {"radius", lens.radius_m}, {"power", lens.power}});
    }
    auto layout = crop_tiles(camera, width_px, height_px, columns, rows);
    if (!layout) {
        return layout.take_error();
    }
    const auto frame = near_plane_frame(camera);
    if (!frame) {
        return frame.take_error_in("frustum::lens_tiles()");
    }
    const auto camera_planes = planes(camera);
    if (!camera_planes.far) {
        return detail::error_text("lens_tiles", "needs a finite far plane", "");
    }
    // How much farther the far plane is than the near plane, seen from the eye.
    const T far_ratio = std::abs(camera_planes.far->distance(frame->eye)) /
                        std::abs(camera_planes.near.distance(frame->eye));

    // A moved point of the refraction plane for the pixel position (x, y).
    const auto moved = [&](int x_px, int y_px) {
        const Vec2<T> ndc(T(-1) + T(2) * T(x_px) / T(width_px), T(-1) + T(2) * T(y_px) / T(height_px));
        const Vec2<T> plane_m(ndc.x * frame->half_width_m, ndc.y * frame->half_height_m);
        return frame->point(lens_warp(plane_m, lens));
    };
    std::vector<Tile<T>> tiles = std::move(layout).value();
    for (Tile<T>& tile : tiles) {
        const int x0 = tile.x_px, x1 = tile.x_px + tile.width_px;
        const int y0 = tile.y_px, y1 = tile.y_px + tile.height_px;
        const Vec3<T> bottom_left = moved(x0, y0), bottom_right = moved(x1, y0);
        const Vec3<T> top_right = moved(x1, y1), top_left = moved(x0, y1);
        const Vec3<T> inside = (bottom_left + bottom_right + top_right + top_left) / T(4);
        const Vec3<T>& eye = frame->eye;
        const SidePlanes<T> sides{side_plane(eye, bottom_left, top_left, inside),
                                  side_plane(eye, bottom_right, top_right, inside),
                                  side_plane(eye, bottom_left, bottom_right, inside),
                                  side_plane(eye, top_left, top_right, inside), camera_planes.near};
        // The far plane keeps each moved corner's ray inside up to the
        // camera's far distance (one far point would tilt it into the tile).
        const std::vector<Vec3<T>> far_points{eye + (bottom_left - eye) * far_ratio,
                                              eye + (bottom_right - eye) * far_ratio,
                                              eye + (top_right - eye) * far_ratio,
                                              eye + (top_left - eye) * far_ratio};
        auto pair = from_planes(sides, far_points, camera.depth());
        if (!pair) {
            return detail::error_text("lens_tiles", "a tile's lens frustum is degenerate",
                                      "tile (" + detail::number(tile.column) + ", " + detail::number(tile.row) +
                                          "): " + pair.error());
        }
        tile.pair = std::move(pair).value();
    }
    return tiles;
}

#define FRUSTUM_INSTANTIATE(T)                                                                             \
    template Vec2<T> lens_warp(const Vec2<T>&, const Lens<T>&);                                            \
    template Result<std::vector<Tile<T>>> lens_tiles(const MatrixPair<T>&, const Lens<T>&, int, int, int, int);
FRUSTUM_INSTANTIATE(float)
FRUSTUM_INSTANTIATE(double)

} // namespace frustum
