// Image comparison for tests: per-channel statistics and a visual diff.
#pragma once

#include "image/image.hpp"

#include <frustum/result.hpp>

#include <vector>

namespace image {

struct Diff {
    int pixel_count = 0;
    double mean_abs = 0.0; // mean |a - b| over every channel of every pixel, 0..255
    int max_abs = 0;       // largest |a - b| of any channel, 0..255
    int tolerance = 0;     // the per-channel tolerance compare() was given
    int pixels_over = 0;   // pixels with some channel differing by more than tolerance

    // pixels_over / pixel_count, in [0, 1].
    double fraction_over() const;
};

// Compares all four channels. Errors when either image is invalid or the
// sizes differ, e.g. "image::compare(): sizes must match, got 4x4 and 4x5";
// a negative tolerance is an error too.
frustum::Result<Diff> compare(const Image& a, const Image& b, int per_channel_tolerance);

// The channels compare_masked() reads.
enum class Channels { Rgb, Rgba };

// compare() over the pixels whose mask[y * width + x] is set, of `channels`
// only: pixel_count counts them, mean_abs is over their compared channels
// (0 for an empty mask). Errors as compare(), named "image::compare_masked()",
// and when the mask does not hold width * height entries.
frustum::Result<Diff> compare_masked(const Image& a, const Image& b, const std::vector<bool>& mask, Channels channels,
                                     int per_channel_tolerance);

// |a - b| per RGB channel times `gain` (clamped to 255), alpha 255, so small
// differences become visible when a test saves it next to the two inputs.
frustum::Result<Image> diff_image(const Image& a, const Image& b, int gain = 16);

} // namespace image
