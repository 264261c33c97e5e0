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

// The one per-pixel difference behind compare() and compare_masked(): the
// first `channels` channels of the pixels `mask` selects (null: every pixel).
frustum::Result<Diff> diff_pixels(const Image& a, const Image& b, const std::vector<bool>* mask, std::size_t channels,
                                  int per_channel_tolerance, const char* where) {
    if (auto ok = check_pair(a, b, where); !ok) {
        return ok.take_error();
    }
    if (per_channel_tolerance < 0) {
        return frustum::Error{std::string(where) + ": tolerance must be >= 0, got " +
                              std::to_string(per_channel_tolerance)};
    }
    const std::size_t pixels = a.rgba.size() / 4;
    if (mask != nullptr && mask->size() != pixels) {
        return frustum::Error{std::string(where) + ": the mask must hold " + std::to_string(pixels) +
                              " entries (" + size_text(a) + "), got " + std::to_string(mask->size())};
    }
    Diff diff;
    diff.tolerance = per_channel_tolerance;
    long long sum = 0;
    for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
        if (mask != nullptr && !(*mask)[pixel]) {
            continue;
        }
        ++diff.pixel_count;
        int pixel_max = 0;
        for (std::size_t c = 4 * pixel; c < 4 * pixel + channels; ++c) {
            const int delta = std::abs(int{a.rgba[c]} - int{b.rgba[c]});
            sum += delta;
            pixel_max = std::max(pixel_max, delta);
        }
        diff.max_abs = std::max(diff.max_abs, pixel_max);
        diff.pixels_over += pixel_max > per_channel_tolerance ? 1 : 0;
    }
    const double compared = static_cast<double>(channels) * diff.pixel_count;
    diff.mean_abs = diff.pixel_count > 0 ? static_cast<double>(sum) / compared : 0.0;
    return diff;
}

} // namespace

double Diff::fraction_over() const {
    return pixel_count == 0 ? 0.0 : static_cast<double>(pixels_over) / pixel_count;
}

frustum::Result<Diff> compare(const Image& a, const Image& b, int per_channel_tolerance) {
    return diff_pixels(a, b, nullptr, 4, per_channel_tolerance, "image::compare()");
}

frustum::Result<Diff> compare_masked(const Image& a, const Image& b, const std::vector<bool>& mask, Channels channels,
                                     int per_channel_tolerance) {
    return diff_pixels(a, b, &mask, channels == Channels::Rgb ? 3 : 4, per_channel_tolerance,
                       "image::compare_masked()");
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
