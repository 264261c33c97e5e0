#include "image/image.hpp"

#include <cstddef>
#include <string>

namespace image {
namespace {

std::size_t offset(const Image& image, int x, int y) {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
            static_cast<std::size_t>(x)) * 4;
}

} // namespace

Image make_image(int width, int height, Rgba fill) {
    Image result{width, height, {}};
    result.rgba.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    for (int i = 0; i < width * height; ++i) {
        result.rgba.insert(result.rgba.end(), fill.begin(), fill.end());
    }
    return result;
}

frustum::Status validate(const Image& image, const char* where) {
    const bool sized = image.width > 0 && image.height > 0 &&
                       image.rgba.size() == static_cast<std::size_t>(image.width) *
                                                static_cast<std::size_t>(image.height) * 4;
    if (sized) {
        return {};
    }
    return frustum::Error{std::string(where) +
                          ": image must be non-empty with width*height*4 bytes, got " +
                          std::to_string(image.width) + "x" + std::to_string(image.height) +
                          " with " + std::to_string(image.rgba.size()) + " bytes"};
}

Rgba pixel_at(const Image& image, int x, int y) {
    const std::size_t at = offset(image, x, y);
    return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2], image.rgba[at + 3]};
}

void set_pixel(Image& image, int x, int y, Rgba value) {
    const std::size_t at = offset(image, x, y);
    for (std::size_t c = 0; c < 4; ++c) {
        image.rgba[at + c] = value[c];
    }
}

} // namespace image
