// Paper §5.1: the frame drawn as N x M cropped tiles equals the frame drawn
// whole.
#include "render_test_support.hpp"

#include <frustum/crop.hpp>

TEST_SUITE("gl") {

TEST_CASE("stitched tiles equal the full frame") {
    RENDER_TEST_ANY_RENDERER(r);
    const auto cameras = render_test::showcase_cameras();
    const image::Image full = r->render(plan::Effect::Plain, cameras, render_test::options());
    for (const auto& grid : {std::pair{2, 2}, std::pair{3, 2}, std::pair{4, 4}}) {
        // Plain ints, not a structured binding: INFO and MESSAGE capture in
        // lambdas, which may not capture bindings before C++20.
        const int columns = grid.first, rows = grid.second;
        INFO("tiles " << columns << "x" << rows);
        auto o = render_test::options();
        o.tile_columns = columns;
        o.tile_rows = rows;
        const image::Image tiled = r->render(plan::Effect::Tiles, cameras, o);
        // llvmpipe rasterizes a pixel the same whatever viewport it lies in,
        // and each tile pair maps a world point to the same pixel up to float
        // rounding. Tolerance 2 LSB per channel; at most kEdgePixels pixels
        // (0.02%) may differ more: a triangle edge passing within rounding
        // of a pixel centre can land on either side of it. Measured on this
        // machine: 0, 0 and 1 pixels (2x2, 3x2, 4x4).
        constexpr int kEdgePixels = 8;
        const auto diff = image::compare(full, tiled, 2);
        REQUIRE_MESSAGE(diff.ok(), diff.error());
        MESSAGE(columns << "x" << rows << " tiles vs full: max " << diff->max_abs << ", " << diff->pixels_over
                        << " pixels over " << diff->tolerance);
        CHECK(diff->pixels_over <= kEdgePixels);
        if (diff->pixels_over > kEdgePixels) {
            render_test::save_failure("tiles-" + std::to_string(columns) + "x" + std::to_string(rows), full, tiled);
        }
    }
}

TEST_CASE("--tile-borders paints the seams between tiles and nothing else") {
    RENDER_TEST_ANY_RENDERER(r);
    const auto cameras = render_test::showcase_cameras();
    auto o = render_test::options();
    o.tile_columns = 3;
    o.tile_rows = 2;
    const image::Image plain_tiles = r->render(plan::Effect::Tiles, cameras, o);
    o.tile_borders = true;
    const image::Image bordered = r->render(plan::Effect::Tiles, cameras, o);
    const auto tiles = frustum::crop_tiles(cameras.main.pair, plain_tiles.width, plain_tiles.height, 3, 2);
    REQUIRE(tiles.ok());
    // The seams: the first column and the first row of every tile not at the left or bottom edge.
    const auto on_seam = [&](int x, int row) {
        const int y = plain_tiles.height - 1 - row; // tiles count from the bottom
        for (const frustum::Tile<float>& t : *tiles) {
            const bool inside = x >= t.x_px && x < t.x_px + t.width_px && y >= t.y_px && y < t.y_px + t.height_px;
            if (inside && ((t.x_px > 0 && x == t.x_px) || (t.y_px > 0 && y == t.y_px))) {
                return true;
            }
        }
        return false;
    };
    int seam_pixels = 0, yellow_seam_pixels = 0, changed_elsewhere = 0;
    for (int row = 0; row < plain_tiles.height; ++row) {
        for (int x = 0; x < plain_tiles.width; ++x) {
            const image::Rgba a = image::pixel_at(plain_tiles, x, row), b = image::pixel_at(bordered, x, row);
            if (on_seam(x, row)) {
                ++seam_pixels;
                yellow_seam_pixels += b[0] == 255 && b[1] == 217 && b[2] == 26 ? 1 : 0; // (1, 0.85, 0.1)
            } else {
                changed_elsewhere += a == b ? 0 : 1;
            }
        }
    }
    // Two vertical seams the full height, one horizontal seam the full width (the crossings once).
    CHECK(seam_pixels == 2 * plain_tiles.height + plain_tiles.width - 2);
    CHECK(yellow_seam_pixels == seam_pixels);
    CHECK(changed_elsewhere == 0);
    if (yellow_seam_pixels != seam_pixels || changed_elsewhere != 0) {
        render_test::save_failure("tile-borders", plain_tiles, bordered);
    }
}

} // TEST_SUITE
