// crop / uncrop / crop_tiles (paper §5.1, eq. 14-15; erratum 1: the
// offset is from the BOTTOM-left).
#include "support.hpp"

using namespace mtest;
using frustum::CropRect;
using frustum::DepthRange;

namespace {

// eq. 14 written literally in the paper's row-vector form, then transposed
// for the column convention: P' = P cropMat  <=>  M' = cropMat^T M, and
// (P')^-1 = invCropMat P^-1  <=>  inv' = inv invCropMat^T.
glm::dmat4 paper_crop_mat(const CropRect<double>& r) {
    const double x = r.x / r.width, y = r.y / r.height;
    const double w = r.full_width / r.width, h = r.full_height / r.height;
    return from_rows<double>({w, 0, 0, 0}, {0, h, 0, 0}, {0, 0, 1, 0}, {w - 1 - 2 * x, h - 1 - 2 * y, 0, 1});
}
glm::dmat4 paper_inv_crop_mat(const CropRect<double>& r) {
    const double x = r.x / r.width, y = r.y / r.height;
    const double rw = r.width / r.full_width, rh = r.height / r.full_height;
    return from_rows<double>({rw, 0, 0, 0}, {0, rh, 0, 0}, {0, 0, 1, 0},
                            {-1 + rw + 2 * x * rw, -1 + rh + 2 * y * rh, 0, 1});
}

CropRect<double> random_rect(Random& rng) {
    const double fw = rng.uniform(1, 4000), fh = rng.uniform(1, 4000);
    const double w = fw * rng.uniform(0.05, 1), h = fh * rng.uniform(0.05, 1);
    return {rng.uniform(0, fw - w), rng.uniform(0, fh - h), w, h, fw, fh};
}

// A random camera, reflected half of the time (the winding flag rides along).
template <class T>
MatrixPair<T> maybe_reflected(Random& rng) {
    const MatrixPair<T> pair = make<T>(random_camera(rng));
    if (!rng.coin()) {
        return pair;
    }
    const auto r = frustum::reflect(pair, Plane<T>(0, 1, 0, 3));
    REQUIRE(r.ok());
    return *r;
}

template <class T>
CropRect<T> as(const CropRect<double>& r) {
    return {T(r.x), T(r.y), T(r.width), T(r.height), T(r.full_width), T(r.full_height)};
}

} // namespace

TEST_SUITE("math") {

TEST_CASE("crop: the sparse form equals the explicit cropMat product of eq. 14") {
    for_each_random_camera<double>(91, 1000, [&](Random& rng, const CameraSpec&, const MatrixPair<double>& pair) {
        const CropRect<double> rect = random_rect(rng);
        const glm::dmat4 crop_mat = paper_crop_mat(rect), inv_crop_mat = paper_inv_crop_mat(rect);
        // The paper's two matrices are inverses of each other.
        CHECK(glm::dmat4(crop_mat * inv_crop_mat) == close_abs(glm::dmat4(1), 1e-12));
        const auto cropped = frustum::crop(pair, rect);
        REQUIRE_MESSAGE(cropped.ok(), cropped.error());
        CHECK(column_relative_diff(cropped->matrix(), glm::dmat4(glm::transpose(crop_mat) * pair.matrix())) <= 1e-12);
        CHECK(column_relative_diff(cropped->inverse(), glm::dmat4(pair.inverse() * glm::transpose(inv_crop_mat))) <=
              1e-12);
        // Only rows 0 and 1 change (eq. 15).
        CHECK(frustum::row(cropped->matrix(), 2) == frustum::row(pair.matrix(), 2));
        CHECK(frustum::row(cropped->matrix(), 3) == frustum::row(pair.matrix(), 3));
        CHECK(cropped->inverse()[2] == pair.inverse()[2]);
        CHECK(inverse_residual(*cropped) <= 256 * eps<double>());
    });
}

TEST_CASE_TEMPLATE("crop: offset from the bottom-left; halves and quadrants of the landmark are off_axis windows", T,
                   float, double) {
    // 800 x 600 pixels over the landmark's near window [-1, 1]^2 at near 1.
    // Y = 0 with height 300 is the BOTTOM half, window [-1, 1] x [-1, 0]:
    // y' = h y + (h - 1 - 2 Y/bh) w = 2 y + w, so y = -1 -> -1, y = 0 -> 1.
    for_each_depth_range([&](DepthRange depth) {
        const auto base = frustum::perspective<T>(T(pi / 2), 1, 1, T(10), depth);
        REQUIRE(base.ok());
        const auto bottom = frustum::crop(*base, CropRect<T>{0, 0, 800, 300, 800, 600});
        const auto bottom_window = frustum::off_axis<T>(-1, 1, -1, 0, 1, T(10), depth);
        REQUIRE((bottom.ok() && bottom_window.ok()));
        CHECK(bottom->matrix() == close(bottom_window->matrix(), tight<T>()));
        CHECK(bottom->inverse() == close(bottom_window->inverse(), tight<T>()));
        // At depth 2 the original window is [-2, 2]^2: y = -1.8 is in the
        // bottom half, y = +0.2 just above it.
        const Vec4<T> low = bottom->matrix() * Vec4<T>(0, T(-1.8), -2, 1);
        CHECK(clip_inside(low, depth, 0));
        const Vec4<T> high = bottom->matrix() * Vec4<T>(0, T(0.2), -2, 1);
        CHECK_FALSE(clip_inside(high, depth, 0));
        // Top-right quadrant: X = 400, Y = 300 -> window [0, 1] x [0, 1].
        const auto quadrant = frustum::crop(*base, CropRect<T>{400, 300, 400, 300, 800, 600});
        const auto quadrant_window = frustum::off_axis<T>(0, 1, 0, 1, 1, T(10), depth);
        REQUIRE((quadrant.ok() && quadrant_window.ok()));
        CHECK(quadrant->matrix() == close(quadrant_window->matrix(), tight<T>()));
        // The whole image is the identity crop.
        const auto whole = frustum::crop(*base, CropRect<T>{0, 0, 800, 600, 800, 600});
        REQUIRE(whole.ok());
        CHECK(whole->matrix() == base->matrix());
        CHECK(whole->inverse() == base->inverse());
    });
}

TEST_CASE_TEMPLATE("crop then uncrop returns the original; flags and depth carried", T, float, double) {
    Random rng(92);
    for (int i = 0; i < 1000; ++i) {
        const MatrixPair<T> pair = maybe_reflected<T>(rng);
        const CropRect<T> rect = as<T>(random_rect(rng));
        const auto cropped = frustum::crop(pair, rect);
        REQUIRE_MESSAGE(cropped.ok(), cropped.error());
        const auto back = frustum::uncrop(*cropped, rect);
        REQUIRE(back.ok());
        CHECK(back->flips_winding() == pair.flips_winding());
        CHECK(back->depth() == pair.depth());
        // Scales up to 20 (a 5% crop) and back: a few ulp times 20.
        CHECK(column_relative_diff(back->matrix(), pair.matrix()) <= loose<T>());
        CHECK(column_relative_diff(back->inverse(), pair.inverse()) <= loose<T>());
        CHECK(inverse_residual(*cropped) <= 256 * eps<T>());
    }
}

TEST_CASE_TEMPLATE("crop_tiles cover the image exactly", T, float, double) {
    // 7 x 5 pixels in 3 x 2 tiles: edges at floor(i W / n) -> x 0, 2, 4, 7;
    // y 0, 2, 5. Row 0 is the bottom row.
    const auto base = frustum::perspective<T>(T(1), T(1.4), T(0.5), T(50), DepthRange::ReversedZeroToOne);
    REQUIRE(base.ok());
    const auto tiles = frustum::crop_tiles(*base, 7, 5, 3, 2);
    REQUIRE_MESSAGE(tiles.ok(), tiles.error());
    REQUIRE(tiles->size() == 6);
    const int xs[4] = {0, 2, 4, 7}, ys[3] = {0, 2, 5};
    for (const auto& tile : *tiles) {
        CAPTURE(tile.column);
        CAPTURE(tile.row);
        CHECK(tile.x_px == xs[tile.column]);
        CHECK(tile.width_px == xs[tile.column + 1] - xs[tile.column]);
        CHECK(tile.y_px == ys[tile.row]);
        CHECK(tile.height_px == ys[tile.row + 1] - ys[tile.row]);
        const auto same = frustum::crop(*base, CropRect<T>{T(tile.x_px), T(tile.y_px), T(tile.width_px),
                                                           T(tile.height_px), 7, 5});
        REQUIRE(same.ok());
        CHECK(tile.pair.matrix() == same->matrix());
        CHECK(tile.pair.inverse() == same->inverse());
    }

    // Random cameras and tilings: every random clip point of the original
    // falls in exactly one tile's [-1, 1)^2 (half-open so shared edges
    // count once), at the pixel it should, and each tile pair is a
    // componentwise inverse.
    for_each_random_camera<T>(93, 200, [&](Random& rng, const CameraSpec& c, const MatrixPair<T>& pair) {
        const int w = 1 + rng.index(1920), h = 1 + rng.index(1080);
        const int cols = 1 + rng.index(std::min(w, 8)), rows = 1 + rng.index(std::min(h, 8));
        CAPTURE(w);
        CAPTURE(h);
        CAPTURE(cols);
        CAPTURE(rows);
        const auto all = frustum::crop_tiles(pair, w, h, cols, rows);
        REQUIRE_MESSAGE(all.ok(), all.error());
        REQUIRE(int(all->size()) == cols * rows);
        long long area = 0;
        for (const auto& tile : *all) {
            area += static_cast<long long>(tile.width_px) * tile.height_px;
            CHECK(inverse_residual(tile.pair) <= 256 * eps<T>());
        }
        CHECK(area == static_cast<long long>(w) * h);
        for (int s = 0; s < 20; ++s) {
            const glm::dvec4 u = random_clip_point(rng, c.depth, 0);
            const glm::dvec4 world = glm::dmat4(pair.inverse()) * u;
            // Pixel coordinates of the point, from the bottom-left.
            const double px = (u.x + 1) / 2 * w, py = (u.y + 1) / 2 * h;
            int hits = 0;
            for (const auto& tile : *all) {
                const glm::dvec4 t = glm::dmat4(tile.pair.matrix()) * world;
                const double tx = t.x / t.w, ty = t.y / t.w;
                if (tx >= -1 && tx < 1 && ty >= -1 && ty < 1) {
                    ++hits;
                    // In the tile's pixel rectangle (1e-3 px slack for float).
                    CHECK(px >= tile.x_px - 1e-3);
                    CHECK(px <= tile.x_px + tile.width_px + 1e-3);
                    CHECK(py >= tile.y_px - 1e-3);
                    CHECK(py <= tile.y_px + tile.height_px + 1e-3);
                }
            }
            CHECK(hits == 1);
        }
    });
}

// Bit for bit where the compiler does not fuse multiply-adds (x86-64,
// armhf, wasm, aarch64 with -ffp-contract=off). Where it may (__FP_FAST_FMA:
// aarch64 with GCC's default contraction), the grid's loop can hoist the
// row's product b inv_1 out of the tile loop and round it before the
// subtraction crop() fuses, so inverse column 3 may move by an ulp of its
// largest entry (docs/porting.md, per-variant drift).
template <class T>
bool same_tile_inverse(const frustum::Mat4<T>& batch, const frustum::Mat4<T>& single) {
#if defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF)
    if (batch[0] != single[0] || batch[1] != single[1] || batch[2] != single[2]) {
        return false;
    }
    T largest = 0;
    for (int i = 0; i < 4; ++i) {
        largest = std::max(largest, std::abs(single[3][i]));
    }
    for (int i = 0; i < 4; ++i) {
        if (!(std::abs(batch[3][i] - single[3][i]) <= 2 * std::numeric_limits<T>::epsilon() * largest)) {
            return false;
        }
    }
    return true;
#else
    return batch == single;
#endif
}

TEST_CASE_TEMPLATE("crop_tiles into a TileGrid: every tile is crop() of its rectangle, bit for bit", T, float,
                   double) {
    // One grid reused across sizes that grow and shrink (its storage is
    // kept), cameras in every depth range, half of them reflected (the
    // winding flag rides along), grids from 1 x 1 up to 40 x 33.
    Random rng(94);
    frustum::TileGrid<T> grid;
    for (int i = 0; i < 120; ++i) {
        const MatrixPair<T> pair = maybe_reflected<T>(rng);
        const int w = 40 + rng.index(1900), h = 33 + rng.index(1050);
        const int cols = 1 + rng.index(40), rows = 1 + rng.index(33);
        CAPTURE(w);
        CAPTURE(h);
        CAPTURE(cols);
        CAPTURE(rows);
        const frustum::Status status = frustum::crop_tiles(pair, w, h, cols, rows, grid);
        REQUIRE_MESSAGE(status.ok(), status.error());
        REQUIRE(grid.columns() == cols);
        REQUIRE(grid.rows() == rows);
        REQUIRE(grid.size() == static_cast<std::size_t>(cols * rows));
        REQUIRE(grid.matrices().size() == grid.size());
        REQUIRE(grid.inverses().size() == grid.size());
        const auto tiles = frustum::crop_tiles(pair, w, h, cols, rows);
        REQUIRE(tiles.ok());
        REQUIRE(tiles->size() == grid.size());
        for (int r = 0; r < rows; ++r) {
            for (int col = 0; col < cols; ++col) {
                const std::size_t k = grid.index(col, r);
                const auto same = frustum::crop(pair, CropRect<T>{T(grid.x_px(col)), T(grid.y_px(r)),
                                                                  T(grid.width_px(col)), T(grid.height_px(r)),
                                                                  T(w), T(h)});
                REQUIRE(same.ok());
                // Exact equality: the same IEEE operations in the same order.
                CHECK(grid.matrices()[k] == same->matrix());
                CHECK(same_tile_inverse(grid.inverses()[k], same->inverse()));
                const MatrixPair<T> p = grid.pair(k);
                CHECK(p.matrix() == same->matrix());
                CHECK(p.inverse() == grid.inverses()[k]);
                CHECK(p.depth() == pair.depth());
                CHECK(p.flips_winding() == pair.flips_winding());
                // The vector form is the grid's tiles.
                const frustum::Tile<T>& t = (*tiles)[k];
                const frustum::Tile<T> g = grid.tile(k);
                CHECK(t.column == col);
                CHECK(t.row == r);
                CHECK(g.column == col);
                CHECK(g.row == r);
                CHECK(t.x_px == grid.x_px(col));
                CHECK(t.y_px == grid.y_px(r));
                CHECK(t.width_px == grid.width_px(col));
                CHECK(t.height_px == grid.height_px(r));
                CHECK(t.pair.matrix() == same->matrix());
                CHECK(same_tile_inverse(t.pair.inverse(), same->inverse()));
                CHECK(t.pair.flips_winding() == pair.flips_winding());
            }
        }
        CHECK(grid.x_px(0) == 0);
        CHECK(grid.x_px(cols) == w);
        CHECK(grid.y_px(0) == 0);
        CHECK(grid.y_px(rows) == h);
    }
    // A refusal: the same text as the vector form, and nothing left in the grid.
    const MatrixPair<T> pair = make<T>(random_camera(rng));
    const frustum::Status bad = frustum::crop_tiles(pair, 4, 600, 5, 2, grid);
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error() == frustum::crop_tiles(pair, 4, 600, 5, 2).error());
    CHECK(grid.size() == 0);
    CHECK(grid.columns() == 0);
    CHECK(grid.matrices().empty());
}

} // TEST_SUITE
