// An RGBA8 image in memory: 4 bytes per pixel, rows top to bottom, no padding.
#pragma once

#include <frustum/result.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace image {

using Rgba = std::array<std::uint8_t, 4>;

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // width * height * 4 bytes, row 0 = top
};

// An image of the given size filled with one colour. Precondition:
// width, height >= 0 (a programming error otherwise, not user data).
Image make_image(int width, int height, Rgba fill);

// Ok when width and height are > 0 and rgba holds exactly width*height*4
// bytes; the error names `where` and the sizes, e.g.
// "image::write_png(): image must be non-empty with width*height*4 bytes, got 2x2 with 15 bytes".
frustum::Status validate(const Image& image, const char* where);

// Pixel access; (0, 0) is the top-left pixel. Precondition: in bounds.
Rgba pixel_at(const Image& image, int x, int y);
void set_pixel(Image& image, int x, int y, Rgba value);

} // namespace image
