#include "image_decode.hpp"

#include <stb/stb_image.h>

#include <climits>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

namespace scene::detail {

namespace {

bool is_png_or_jpeg(const std::uint8_t* bytes, std::size_t size_bytes) {
    static const std::uint8_t png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static const std::uint8_t jpeg[3] = {0xFF, 0xD8, 0xFF};
    return (size_bytes >= 8 && std::memcmp(bytes, png, 8) == 0) ||
           (size_bytes >= 3 && std::memcmp(bytes, jpeg, 3) == 0);
}

} // namespace

frustum::Result<image::Image> decode_rgba8(const std::uint8_t* bytes, std::size_t size_bytes,
                                    std::uint64_t max_pixels, std::uint64_t max_rgba_bytes,
                                    const std::string& budget_note) {
    using frustum::Error;
    if (size_bytes == 0) {
        return Error{"no image bytes"};
    }
    if (size_bytes > static_cast<std::size_t>(INT_MAX)) {
        return Error{"encoded image has " + std::to_string(size_bytes) +
                     " bytes, more than stb_image accepts"};
    }
    if (!is_png_or_jpeg(bytes, size_bytes)) {
        char first[16];
        std::snprintf(first, sizeof first, "%02X %02X %02X", bytes[0],
                      size_bytes > 1 ? bytes[1] : 0, size_bytes > 2 ? bytes[2] : 0);
        return Error{std::string("the image is neither PNG nor JPEG (first bytes ") + first +
                     "), the formats glTF 2.0 allows"};
    }
    const int length = static_cast<int>(size_bytes);
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, length, &width, &height, &channels)) {
        return Error{std::string("cannot decode the image header: ") + stbi_failure_reason()};
    }
    const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
    if (width <= 0 || height <= 0 || pixels > max_pixels) {
        return Error{"image is " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels, the limit is " + std::to_string(max_pixels) + " pixels"};
    }
    if (pixels * 4 > max_rgba_bytes) {
        return Error{"image is " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels, " + std::to_string(pixels * 4) + " bytes decoded, more than the " +
                     std::to_string(max_rgba_bytes) + " bytes left" + budget_note};
    }
    stbi_set_flip_vertically_on_load_thread(0);
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels_rgba(
        stbi_load_from_memory(bytes, length, &width, &height, &channels, 4), &stbi_image_free);
    if (!pixels_rgba) {
        return Error{std::string("cannot decode the image: ") + stbi_failure_reason()};
    }
    image::Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(pixels_rgba.get(),
                      pixels_rgba.get() + std::size_t(width) * std::size_t(height) * 4);
    return image;
}

} // namespace scene::detail
