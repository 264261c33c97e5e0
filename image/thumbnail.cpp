#include "image/thumbnail.hpp"

#include <algorithm>

namespace image {

Thumbnail::Thumbnail(int width_px, int height_px, int max_side_px)
    : width_px_(width_px), height_px_(height_px),
      factor_((std::max(width_px, height_px) + max_side_px - 1) / max_side_px) {
    const int w = (width_px + factor_ - 1) / factor_;
    const int h = (height_px + factor_ - 1) / factor_;
    sums_.assign(static_cast<std::size_t>(w) * 4, 0);
    thumbnail_ = make_image(w, h, {0, 0, 0, 0});
}

void Thumbnail::add_rows(const Image& rows) {
    const int k = factor_;
    for (int y = 0; y < rows.height && rows_added_ < height_px_; ++y, ++rows_added_) {
        const std::uint8_t* row = rows.rgba.data() + static_cast<std::size_t>(y) * rows.width * 4;
        for (int x = 0; x < width_px_; ++x) {
            std::uint32_t* sum = &sums_[static_cast<std::size_t>(x / k) * 4];
            for (int c = 0; c < 4; ++c) {
                sum[c] += row[static_cast<std::size_t>(x) * 4 + c];
            }
        }
        ++band_rows_;
        if (band_rows_ == k || rows_added_ + 1 == height_px_) {
            emit_band();
        }
    }
}

// The band's sums -> one thumbnail row (each block's mean, rounded to nearest).
void Thumbnail::emit_band() {
    const int k = factor_;
    const int out_y = rows_added_ / k;
    for (int tx = 0; tx < thumbnail_.width; ++tx) {
        const int block_w = std::min(k, width_px_ - tx * k);
        const std::uint32_t count = static_cast<std::uint32_t>(block_w * band_rows_);
        Rgba mean{};
        for (int c = 0; c < 4; ++c) {
            std::uint32_t& sum = sums_[static_cast<std::size_t>(tx) * 4 + c];
            mean[c] = static_cast<std::uint8_t>((sum + count / 2) / count);
            sum = 0;
        }
        set_pixel(thumbnail_, tx, out_y, mean);
    }
    band_rows_ = 0;
}

} // namespace image
