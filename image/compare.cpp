#include "image/compare.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace image {
namespace {

std::string size_text(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

frustum::Status check_pair(const Image& a, const Image& b, const char* where) {
    if (auto valid = validate(a, where); !valid) {
        return valid;
    }
    if (auto valid = validate(b, where); !valid) {
        return valid;
    }
    if (a.width != b.width || a.height != b.height) {
        return frustum::Error{std::string(where) + ": sizes must match, got " + size_text(a) +
                              " and " + size_text(b)};
    }
    return {};
}

} // namespace

double Diff::fraction_over() const {
    return pixel_count == 0 ? 0.0 : static_cast<double>(pixels_over) / pixel_count;
}

frustum::Result<Diff> compare(const Image& a, const Image& b, int per_channel_tolerance) {
    if (auto ok = check_pair(a, b, "image::compare()"); !ok) {
        return ok.take_error();
    }
    if (per_channel_tolerance < 0) {
        return frustum::Error{"image::compare(): tolerance must be >= 0, got " +
                              std::to_string(per_channel_tolerance)};
    }
    Diff diff;
    diff.pixel_count = a.width * a.height;
    diff.tolerance = per_channel_tolerance;
    double sum = 0.0;
    for (std::size_t pixel = 0; pixel < a.rgba.size(); pixel += 4) {
        int pixel_max = 0;
        for (std::size_t c = pixel; c < pixel + 4; ++c) {
            const int delta = std::abs(int{a.rgba[c]} - int{b.rgba[c]});
            sum += delta;
            pixel_max = std::max(pixel_max, delta);
        }
        diff.max_abs = std::max(diff.max_abs, pixel_max);
        diff.pixels_over += pixel_max > per_channel_tolerance ? 1 : 0;
    }
    diff.mean_abs = sum / static_cast<double>(a.rgba.size());
    return diff;
}

frustum::Result<Image> diff_image(const Image& a, const Image& b, int gain) {
    if (auto ok = check_pair(a, b, "image::diff_image()"); !ok) {
        return ok.take_error();
    }
    if (gain < 1) {
        return frustum::Error{"image::diff_image(): gain must be >= 1, got " +
                              std::to_string(gain)};
    }
    Image result{a.width, a.height, std::vector<std::uint8_t>(a.rgba.size())};
    for (std::size_t c = 0; c < a.rgba.size(); ++c) {
        const bool alpha = c % 4 == 3;
        const int delta = std::abs(int{a.rgba[c]} - int{b.rgba[c]}) * gain;
        result.rgba[c] = alpha ? 255 : static_cast<std::uint8_t>(std::min(delta, 255));
    }
    return result;
}

} // namespace image
