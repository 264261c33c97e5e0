// Paper §5.1: the frame drawn as N x M cropped tiles equals the frame drawn
// whole.
#include "render_test_support.hpp"

TEST_SUITE("gl") {

TEST_CASE("stitched tiles equal the full frame") {
    auto r = render_test::make_any_renderer();
    if (!r) {
        return;
    }
    const auto cameras = render_test::showcase_cameras();
    const image::Image full = r->render(render::Effect::Plain, cameras, render_test::options());
    for (const auto& grid : {std::pair{2, 2}, std::pair{3, 2}, std::pair{4, 4}}) {
        // Plain ints, not a structured binding: INFO and MESSAGE capture in
        // lambdas, which may not capture bindings before C++20.
        const int columns = grid.first, rows = grid.second;
        INFO("tiles " << columns << "x" << rows);
        auto o = render_test::options();
        o.tile_columns = columns;
        o.tile_rows = rows;
        const image::Image tiled = r->render(render::Effect::Tiles, cameras, o);
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

} // TEST_SUITE
