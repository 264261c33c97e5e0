// A downscaled copy of an image that is never held whole (a poster streamed
// to disk, image/png_stream.hpp): rows are added top to bottom as they come
// and box-filtered by one whole factor k, so only one band of k rows of
// sums is kept.
#pragma once

#include "image/image.hpp"

#include <cstdint>
#include <vector>

namespace image {

class Thumbnail {
public:
    // k = ceil(max(width_px, height_px) / max_side_px) (1 for an image that
    // already fits): the thumbnail is ceil(width_px / k) x ceil(height_px / k),
    // each pixel the mean of its k x k block (the blocks of the last column
    // and row are cut to the image). Preconditions: all three >= 1.
    Thumbnail(int width_px, int height_px, int max_side_px);

    // The image's next rows (rows.width == width_px), top to bottom; rows past
    // height_px are ignored.
    void add_rows(const Image& rows);

    // The thumbnail so far (complete once every row was added).
    const Image& image() const { return thumbnail_; }
    int factor() const { return factor_; }

private:
    void emit_band();
    int width_px_;
    int height_px_;
    int factor_;
    int rows_added_ = 0;
    int band_rows_ = 0;                 // rows summed into sums_ so far
    std::vector<std::uint32_t> sums_;   // per thumbnail pixel and channel
    Image thumbnail_;
};

} // namespace image
