// image::Thumbnail: the box filter of rows as they come equals the mean of
// each k x k block computed here directly, whatever the bands.
#include <image/image.hpp>
#include <image/thumbnail.hpp>

#include <doctest/doctest.h>

#include <cstdint>

namespace {

image::Image ramp(int w, int h) {
    image::Image picture = image::make_image(w, h, {0, 0, 0, 0});
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            image::set_pixel(picture, x, y,
                             {static_cast<std::uint8_t>(x * 9), static_cast<std::uint8_t>(y * 17),
                              static_cast<std::uint8_t>((x * y) % 251), 255});
        }
    }
    return picture;
}

// rows [top, top + h) of `picture`.
image::Image band(const image::Image& picture, int top, int h) {
    image::Image out{picture.width, h, {}};
    out.rgba.assign(picture.rgba.begin() + static_cast<long>(top) * picture.width * 4,
                    picture.rgba.begin() + static_cast<long>(top + h) * picture.width * 4);
    return out;
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("thumbnail: rows added in bands give each k x k block's rounded mean, edge blocks cut") {
    const int w = 23, h = 17; // max side 8 -> k = ceil(23 / 8) = 3 -> 8 x 6, last column 2 wide, last row 2 high
    const image::Image picture = ramp(w, h);
    image::Thumbnail thumbnail(w, h, 8);
    CHECK(thumbnail.factor() == 3);
    int top = 0;
    for (int rows : {2, 5, 1, 9}) {
        thumbnail.add_rows(band(picture, top, rows));
        top += rows;
    }
    const image::Image& small = thumbnail.image();
    REQUIRE(small.width == 8);
    REQUIRE(small.height == 6);
    for (int ty = 0; ty < 6; ++ty) {
        for (int tx = 0; tx < 8; ++tx) {
            for (int c = 0; c < 4; ++c) {
                int sum = 0, count = 0;
                for (int y = ty * 3; y < std::min(h, ty * 3 + 3); ++y) {
                    for (int x = tx * 3; x < std::min(w, tx * 3 + 3); ++x) {
                        sum += image::pixel_at(picture, x, y)[c];
                        ++count;
                    }
                }
                CAPTURE(tx);
                CAPTURE(ty);
                CHECK(image::pixel_at(small, tx, ty)[c] == (sum + count / 2) / count);
            }
        }
    }
    image::Thumbnail same(5, 4, 8); // fits: k = 1, a copy
    same.add_rows(ramp(5, 4));
    CHECK(same.factor() == 1);
    CHECK(same.image().rgba == ramp(5, 4).rgba);
}

} // TEST_SUITE
