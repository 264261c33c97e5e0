// Paper §5.4: lens refraction tiles.
#include "support.hpp"

#include <frustum/detail/lens_matrices.hpp>

using namespace frustum;

namespace {

MatrixPair<double> lens_camera(DepthRange depth) {
    const auto projection = perspective(1.0, 1.5, 0.5, std::optional<double>(50.0), depth);
    const auto view = look_at(glm::dvec3(1, 2, 5), glm::dvec3(0, 0, 0), glm::dvec3(0, 1, 0));
    return compose(*projection, *view);
}

// The point at `distance_m` from the eye along the camera's view axis.
glm::dvec3 frame_point_on_axis(const MatrixPair<double>& camera, double distance_m) {
    const auto frame = near_plane_frame(camera);
    const glm::dvec3 axis = glm::normalize(frame->center - frame->eye);
    return frame->eye + distance_m * axis;
}

// Max |a - s b| / |s| over entries, s fitted on the largest entry of b:
// "equal up to a positive factor".
double factor_deviation(const glm::dmat4& a, const glm::dmat4& b, double* factor) {
    int best_c = 0, best_r = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(b[c][r]) > std::abs(b[best_c][best_r])) best_c = c, best_r = r;
    const double s = a[best_c][best_r] / b[best_c][best_r];
    *factor = s;
    double worst = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) worst = std::max(worst, std::abs(a[c][r] - s * b[c][r]) / std::abs(s));
    return worst;
}

// Every point of a tile's four edges from the near plane out to the
// camera's far distance is inside the tile frustum's depth range (the edges
// lie on the side planes, so only z and w are checked).
void check_edges_reach_far(const MatrixPair<double>& camera, const Lens<double>& lens) {
    const auto frame = near_plane_frame(camera);
    REQUIRE(frame.ok());
    const auto tiles = lens_tiles(camera, lens, 256, 256, 8, 8);
    REQUIRE(tiles.ok());
    const double far_ratio = far_distance(camera).value() / near_distance(camera).value();
    const double z_near = clip_z_near<double>(camera.depth()), z_far = clip_z_far<double>(camera.depth());
    for (const auto& tile : *tiles) {
        const auto k = key_points(tile.pair);
        for (int i = 0; i < 4; ++i) {
            const glm::dvec3 near_corner(to_point(k.corners[i], 1e-12));
            for (double t : {1.0 + 1e-6, 2.0, 10.0, 0.5 * far_ratio, far_ratio * (1.0 - 1e-9)}) {
                const glm::dvec3 point = frame->eye + t * (near_corner - frame->eye);
                const glm::dvec4 clip = tile.pair.matrix() * glm::dvec4(point, 1.0);
                CHECK(clip.w > 0.0);
                const double depth = clip.z / clip.w;
                CHECK((depth - z_near) * (z_far - z_near) >= -1e-9);
                CHECK((z_far - depth) * (z_far - z_near) >= -1e-9);
            }
        }
        CHECK(mtest::inverse_residual(tile.pair) < 1e-10);
    }
}

} // namespace

TEST_SUITE("math") {

TEST_CASE("lens_warp follows eq. 34: points inside R approach C for p > 1, outside move away") {
    const Lens<double> lens{glm::dvec2(0.1, -0.2), 0.5, 2.0};
    // r = 0.5: |v| = 0.25 -> R r^2 = 0.125 along the same direction.
    const glm::dvec2 inside = lens_warp(glm::dvec2(0.1 + 0.25, -0.2), lens);
    CHECK(inside.x == doctest::Approx(0.1 + 0.125).epsilon(mtest::tight<double>()));
    CHECK(inside.y == doctest::Approx(-0.2).epsilon(mtest::tight<double>()));
    // r = 2: |v| = 1 -> R r^2 = 2.
    const glm::dvec2 outside = lens_warp(glm::dvec2(0.1, -0.2 + 1.0), lens);
    CHECK(outside.y == doctest::Approx(-0.2 + 2.0).epsilon(mtest::tight<double>()));
    // On the rim and at the centre nothing moves.
    CHECK(lens_warp(glm::dvec2(0.1 + 0.5, -0.2), lens).x == doctest::Approx(0.6).epsilon(mtest::tight<double>()));
    CHECK(lens_warp(lens.center_m, lens) == lens.center_m);
}

TEST_CASE("lens tiles with power 1 are exactly the crop tiles (up to a positive factor)") {
    for (DepthRange depth : mtest::all_depth_ranges) {
        CAPTURE(depth);
        const auto camera = lens_camera(depth);
        const Lens<double> identity_lens{glm::dvec2(0.05, 0.0), 0.15, 1.0};
        const auto lens = lens_tiles(camera, identity_lens, 64, 48, 4, 3);
        const auto crops = crop_tiles(camera, 64, 48, 4, 3);
        REQUIRE(lens.ok());
        REQUIRE(crops.ok());
        REQUIRE(lens->size() == crops->size());
        for (std::size_t i = 0; i < lens->size(); ++i) {
            double factor = 0.0;
            CHECK(factor_deviation((*lens)[i].pair.matrix(), (*crops)[i].pair.matrix(), &factor) < 1e-9);
            CHECK(factor > 0.0);
            CHECK(mtest::inverse_residual((*lens)[i].pair) < 1e-12);
        }
    }
}

TEST_CASE("lens tiles magnify inside the radius and keep shared corners seamless") {
    const auto camera = lens_camera(DepthRange::ZeroToOne);
    const auto frame = near_plane_frame(camera);
    REQUIRE(frame.ok());
    const Lens<double> lens{glm::dvec2(0.0, 0.0), 0.6 * frame->half_height_m, 2.0};
    const int columns = 8, rows = 8;
    const auto tiles = lens_tiles(camera, lens, 256, 256, columns, rows);
    REQUIRE(tiles.ok());
    const auto near_area = [&](const Tile<double>& t) {
        const auto k = key_points(t.pair);
        const glm::dvec3 c1(to_point(k.corners[0], 1e-12)), c2(to_point(k.corners[1], 1e-12)),
            c3(to_point(k.corners[2], 1e-12));
        return glm::length(c1 - c2) * glm::length(c2 - c3);
    };
    const auto plain = crop_tiles(camera, 256, 256, columns, rows);
    // A central tile sees a smaller patch of the refraction plane than
    // without the lens (magnification); a corner tile (outside R) a larger one.
    const auto& centre = (*tiles)[3 * columns + 3];
    const auto& corner = (*tiles)[0];
    CHECK(near_area(centre) < 0.8 * near_area((*plain)[3 * columns + 3]));
    CHECK(near_area(corner) > 1.2 * near_area((*plain)[0]));
    // Neighbours share their moved corner: tile (0,0)'s C1 (top right of its
    // near face) is tile (1,1)'s C3 (bottom left).
    const auto a = to_point(key_points((*tiles)[0].pair).corners[0], 1e-12);
    const auto b = to_point(key_points((*tiles)[columns + 1].pair).corners[2], 1e-12);
    CHECK(mtest::max_diff(a, b) < 1e-12);
    for (const auto& t : *tiles) {
        CHECK(mtest::inverse_residual(t.pair) < 1e-12);
    }
}

TEST_CASE("lens tiles keep every edge inside up to the camera's far distance") {
    const auto camera = lens_camera(DepthRange::ZeroToOne);
    const auto frame = near_plane_frame(camera);
    REQUIRE(frame.ok());
    // A magnifier as the demo uses it (R = 0.6 half-height, p = 2) and an
    // extreme one (p = 3, R = half the half-height: outer corners thrown tens
    // of near-plane sizes out, tiles far from parallelograms, whose far
    // corners fall behind the eye: see lens.hpp).
    check_edges_reach_far(camera, Lens<double>{glm::dvec2(0.1, -0.05), 0.6 * frame->half_height_m, 2.0});
    check_edges_reach_far(camera, Lens<double>{glm::dvec2(0.1, -0.05), 0.5 * frame->half_height_m, 3.0});
    for (DepthRange depth : {DepthRange::MinusOneToOne, DepthRange::ReversedZeroToOne}) {
        CAPTURE(depth);
        check_edges_reach_far(lens_camera(depth), Lens<double>{glm::dvec2(0.0), 0.6 * frame->half_height_m, 2.0});
    }
}

TEST_CASE("from_planes with several far points takes the nearest plane that keeps them all inside") {
    const auto camera = lens_camera(DepthRange::ZeroToOne);
    const auto p = planes(camera);
    const SidePlanes<double> sides{p.left, p.right, p.bottom, p.top, p.near};
    const glm::dvec3 near_point(frame_point_on_axis(camera, 5.0)), far_point(frame_point_on_axis(camera, 20.0));
    const auto both = from_planes(sides, std::vector<glm::dvec3>{far_point, near_point}, DepthRange::ZeroToOne);
    // Keeping the point at 20 m inside keeps the one at 5 m inside too.
    const auto nearest = from_planes(sides, far_point, DepthRange::ZeroToOne);
    REQUIRE(both.ok());
    REQUIRE(nearest.ok());
    double factor = 0.0;
    CHECK(factor_deviation(both->matrix(), nearest->matrix(), &factor) < 1e-12);
    CHECK_FALSE(from_planes(sides, std::vector<glm::dvec3>{}, DepthRange::ZeroToOne).ok());
}

// One tile's lens frustum built on its own by §4's plane construction, as
// lens_tiles() built it before issue 34: four warped corners, four unit side
// planes and a vector of four far points per tile, relative to the eye,
// then moved to the world (M T(-eye), T(eye) M^-1). lens_tiles() now
// assembles the same frustum from shared corners and edge normals (the
// inverse from points, §3.2), equal up to a positive factor.
template <class T>
Result<MatrixPair<T>> lens_tile_alone(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px,
                                      int height_px, int x0, int x1, int y0, int y1) {
    const auto frame = near_plane_frame(camera);
    const auto camera_planes = planes(camera);
    const T far_ratio = std::abs(camera_planes.far->distance(frame->eye)) /
                        std::abs(camera_planes.near.distance(frame->eye));
    NearPlaneFrame<T> relative = *frame;
    relative.center = frame->center - frame->eye;
    const auto moved = [&](int x_px, int y_px) {
        const Vec2<T> ndc(T(-1) + T(2) * T(x_px) / T(width_px), T(-1) + T(2) * T(y_px) / T(height_px));
        const Vec2<T> plane_m(ndc.x * frame->half_width_m, ndc.y * frame->half_height_m);
        return relative.point(lens_warp(plane_m, lens));
    };
    const auto side = [](const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& inside) {
        return Plane<T>::at(glm::normalize(glm::cross(a, b)), Vec3<T>(T(0))).facing(inside);
    };
    const Vec3<T> bl = moved(x0, y0), br = moved(x1, y0), tr = moved(x1, y1), tl = moved(x0, y1);
    const Vec3<T> inside = (bl + br + tr + tl) / T(4);
    const SidePlanes<T> sides{side(bl, tl, inside), side(br, tr, inside), side(bl, br, inside),
                              side(tl, tr, inside), Plane<T>::at(camera_planes.near.normal(), relative.center)};
    const std::vector<Vec3<T>> far{bl * far_ratio, br * far_ratio, tr * far_ratio, tl * far_ratio};
    const auto pair = from_planes(sides, far, camera.depth());
    if (!pair) {
        return pair;
    }
    return compose(*pair, RigidTransform<T>::from_rotation_translation(Mat3<T>(T(1)), -frame->eye));
}

// Largest distance between the near corners of `pair` and of `reference`
// (double), relative to the reference corner's distance from the eye. (Far
// corners of tiles that are far from parallelograms are ill-conditioned in
// any construction; tests/bench/lens_accuracy compares them with
// re-inverting.)
template <class T>
double corner_deviation(const MatrixPair<T>& pair, const MatrixPair<double>& reference, const glm::dvec3& eye) {
    const glm::dmat4 inv(pair.inverse());
    double worst = 0.0;
    for (double z : {clip_z_near<double>(reference.depth())}) {
        for (int i = 0; i < 4; ++i) {
            const glm::dvec4 ndc(i == 1 || i == 2 ? 1.0 : -1.0, i >= 2 ? 1.0 : -1.0, z, 1.0);
            const glm::dvec4 a = inv * ndc, b = reference.inverse() * ndc;
            const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
            worst = std::max(worst, glm::length(pa - pb) / glm::length(pb - eye));
        }
    }
    return worst;
}

TEST_CASE_TEMPLATE("lens_tiles into a TileGrid: the vector form bit for bit, the matrices alone and the plane "
                   "construction up to rounding and a positive factor",
                   T, float, double) {
    TileGrid<T> grid, layout;
    std::vector<Mat4<T>> matrices;
    const struct {
        int width_px, height_px, columns, rows;
    } grids[] = {{64, 64, 1, 1}, {64, 48, 3, 2}, {256, 256, 8, 8}, {1280, 720, 7, 5}, {1280, 720, 32, 32}};
    // Float: near corners within 2e-5 of the double plane construction's
    // (about 170 eps), residual |M M^-1 - I| within 128 eps (32 x 32 tiles:
    // 1.0e-5 measured), the re-inverting baseline's M within 2e-3 (its m3
    // sums planes of nearly opposite normals, so a tile's width cancels:
    // below 1e-4 on x86-64, 7.2e-4 measured on aarch64 with FMA contraction
    // at 32 x 32 tiles; the baseline is the benchmark's, not the product's).
    const double corner_tolerance = std::is_same_v<T, float> ? 2e-5 : 1e-12;
    const double residual_tolerance = std::is_same_v<T, float> ? 128 * 1.2e-7 : 128 * 2.3e-16;
    const double baseline_tolerance = std::is_same_v<T, float> ? 2e-3 : 1e-11;
    for (DepthRange depth : mtest::all_depth_ranges) {
        const MatrixPair<double> camera_d = lens_camera(depth);
        const MatrixPair<T> camera = camera_d.template cast<T>();
        const auto frame = near_plane_frame(camera);
        REQUIRE(frame.ok());
        const auto frame_d = near_plane_frame(camera_d);
        for (const T power : {T(2), T(1.5), T(0.7)}) {
            const Lens<T> lens{Vec2<T>(T(0.1), T(-0.05)) * frame->half_height_m, T(0.6) * frame->half_height_m,
                               power};
            const Lens<double> lens_d{glm::dvec2(lens.center_m), double(lens.radius_m), double(power)};
            for (const auto& g : grids) {
                CAPTURE(depth);
                CAPTURE(power);
                CAPTURE(g.columns);
                CAPTURE(g.rows);
                const Status status = lens_tiles(camera, lens, g.width_px, g.height_px, g.columns, g.rows, grid);
                REQUIRE_MESSAGE(status.ok(), status.error());
                const auto tiles = lens_tiles(camera, lens, g.width_px, g.height_px, g.columns, g.rows);
                REQUIRE(tiles.ok());
                const Status only = detail::lens_tile_matrices(camera, lens, g.width_px, g.height_px, g.columns,
                                                               g.rows, layout, matrices);
                REQUIRE(only.ok());
                REQUIRE(grid.size() == tiles->size());
                REQUIRE(matrices.size() == grid.size());
                double worst_corner = 0.0, worst_residual = 0.0, worst_baseline = 0.0;
                for (std::size_t k = 0; k < grid.size(); ++k) {
                    const Tile<T>& tile = (*tiles)[k];
                    CHECK(tile.pair.matrix() == grid.matrices()[k]);
                    CHECK(tile.pair.inverse() == grid.inverses()[k]);
                    // The baseline's matrix (from the edge planes alone): the same M to rounding.
                    double baseline = 0.0;
                    for (int col = 0; col < 4; ++col) {
                        baseline = std::max(baseline, glm::length(glm::dvec4(matrices[k][col]) -
                                                                  glm::dvec4(grid.matrices()[k][col])) /
                                                          glm::length(glm::dvec4(grid.matrices()[k][col])));
                    }
                    worst_baseline = std::max(worst_baseline, baseline);
                    CHECK(grid.pair(k).depth() == depth);
                    CHECK_FALSE(grid.pair(k).flips_winding());
                    CHECK(grid.tile(k).x_px == tile.x_px);
                    CHECK(grid.tile(k).height_px == tile.height_px);
                    const auto alone = lens_tile_alone(camera_d, lens_d, g.width_px, g.height_px, tile.x_px,
                                                       tile.x_px + tile.width_px, tile.y_px,
                                                       tile.y_px + tile.height_px);
                    REQUIRE(alone.ok());
                    worst_corner = std::max(worst_corner, corner_deviation(grid.pair(k), *alone, frame_d->eye));
                    worst_residual = std::max(worst_residual, mtest::inverse_residual(grid.pair(k)));
                    // w > 0 inside: the near face's centre maps to w > 0 as in the plane construction.
                    const glm::dvec4 centre = alone->matrix() * (alone->inverse() * glm::dvec4(0, 0, clip_z_near<double>(depth), 1));
                    const glm::dvec4 ours = glm::dmat4(grid.matrices()[k]) * (alone->inverse() * glm::dvec4(0, 0, clip_z_near<double>(depth), 1));
                    CHECK(ours.w * centre.w > 0.0);
                }
                CHECK(worst_corner < corner_tolerance);
                CHECK(worst_residual < residual_tolerance);
                CHECK(worst_baseline < baseline_tolerance);
            }
        }
    }
    // A refusal: the vector form's text, and the grid left empty.
    const auto ortho = orthographic<double>(-1, 1, -1, 1, 1, 10, DepthRange::ZeroToOne);
    REQUIRE(ortho.ok());
    const MatrixPair<T> flat = ortho->template cast<T>();
    const Lens<T> lens{Vec2<T>(T(0)), T(0.5), T(2)};
    const Status bad = lens_tiles(flat, lens, 64, 64, 2, 2, grid);
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error() == lens_tiles(flat, lens, 64, 64, 2, 2).error());
    CHECK(grid.size() == 0);
}

TEST_CASE("lens_tiles rejects bad lenses and cameras") {
    const auto camera = lens_camera(DepthRange::ZeroToOne);
    const auto zero_radius = lens_tiles(camera, Lens<double>{glm::dvec2(0.0), 0.0, 2.0}, 64, 64, 2, 2);
    CHECK_FALSE(zero_radius.ok());
    CHECK(zero_radius.error().find("radius > 0") != std::string::npos);
    const auto nan_power = lens_tiles(camera, Lens<double>{glm::dvec2(0.0), 1.0, std::nan("")}, 64, 64, 2, 2);
    CHECK_FALSE(nan_power.ok());
    const auto ortho = orthographic(-1.0, 1.0, -1.0, 1.0, 0.1, 10.0, DepthRange::ZeroToOne);
    const auto no_eye = lens_tiles(*ortho, Lens<double>{glm::dvec2(0.0), 0.5, 2.0}, 64, 64, 2, 2);
    CHECK_FALSE(no_eye.ok());
    CHECK(no_eye.error().find("perspective") != std::string::npos);
    const auto infinite = perspective(1.0, 1.0, 0.1, std::optional<double>(), DepthRange::ZeroToOne);
    const auto no_far = lens_tiles(*infinite, Lens<double>{glm::dvec2(0.0), 0.05, 2.0}, 64, 64, 2, 2);
    CHECK_FALSE(no_far.ok());
    CHECK(no_far.error().find("finite far plane") != std::string::npos);
}

} // TEST_SUITE
