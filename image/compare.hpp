// Image comparison for tests: per-channel statistics and a visual diff.
#pragma once

#include "image/image.hpp"

#include <frustum/result.hpp>

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

// |a - b| per RGB channel times `gain` (clamped to 255), alpha 255, so small
// differences become visible when a test saves it next to the two inputs.
frustum::Result<Image> diff_image(const Image& a, const Image& b, int gain = 16);

} // namespace image
