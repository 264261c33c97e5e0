#include "render/frame_window.hpp"

#include <algorithm>

namespace render {
namespace {

frustum::CropRect<float> relative_rect(const plan::PixelRect& image, const plan::PixelRect& part) {
    return {static_cast<float>(part.x - image.x), static_cast<float>(part.y - image.y),
            static_cast<float>(part.width),       static_cast<float>(part.height),
            static_cast<float>(image.width),      static_cast<float>(image.height)};
}

// eq. 14 with w = W/bw, x = X/bw: x' = w x + (w - 1 - 2x) per axis (NDC).
glm::vec4 scale_offset(const plan::PixelRect& image, const plan::PixelRect& part) {
    const frustum::CropRect<float> r = relative_rect(image, part);
    const float sx = r.full_width / r.width, sy = r.full_height / r.height;
    return {sx, sy, sx - 1.0f - 2.0f * r.x / r.width, sy - 1.0f - 2.0f * r.y / r.height};
}

} // namespace

FrameWindow whole_frame(int width_px, int height_px) {
    return FrameWindow{width_px, height_px, plan::PixelRect{0, 0, width_px, height_px}};
}

std::optional<plan::PixelRect> intersect(const plan::PixelRect& a, const plan::PixelRect& b) {
    const int x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
    const int x1 = std::min(a.x + a.width, b.x + b.width), y1 = std::min(a.y + a.height, b.y + b.height);
    if (x1 <= x0 || y1 <= y0) {
        return std::nullopt;
    }
    return plan::PixelRect{x0, y0, x1 - x0, y1 - y0};
}

plan::PixelRect bounding(const plan::PixelRect& a, const plan::PixelRect& b) {
    const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.x + a.width, b.x + b.width), y1 = std::max(a.y + a.height, b.y + b.height);
    return plan::PixelRect{x0, y0, x1 - x0, y1 - y0};
}

plan::PixelRect in_target(const FrameWindow& window, const plan::PixelRect& r) {
    return {r.x - window.rect.x, r.y - window.rect.y, r.width, r.height};
}

frustum::Result<frustum::MatrixPair<float>> crop_part(const frustum::MatrixPair<float>& pair,
                                                      const plan::PixelRect& image, const plan::PixelRect& part) {
    if (part.x == image.x && part.y == image.y && part.width == image.width && part.height == image.height) {
        return pair; // the whole image: bit for bit the pair a direct render draws with
    }
    // In double, rounded to float once at the end: the float crop's own
    // rounding (its terms grow with the scale W / bw) would add to the
    // GPU's (test_poster_slow measures both).
    const frustum::CropRect<float> r = relative_rect(image, part);
    auto cropped = frustum::crop(pair.cast<double>(), frustum::CropRect<double>{r.x, r.y, r.width, r.height,
                                                                             r.full_width, r.full_height});
    if (!cropped) {
        return cropped.take_error();
    }
    return cropped->cast<float>();
}

frustum::Result<frustum::MatrixPair<float>> crop_to_window(const frustum::MatrixPair<float>& pair,
                                                           const FrameWindow& window) {
    return crop_part(pair, plan::PixelRect{0, 0, window.full_width_px, window.full_height_px}, window.rect);
}

glm::mat4 crop_part_matrix(const glm::mat4& matrix, const plan::PixelRect& image, const plan::PixelRect& part) {
    const glm::vec4 c = scale_offset(image, part);
    glm::mat4 out = matrix;
    for (int column = 0; column < 4; ++column) { // glm: matrix[column][row]
        out[column][0] = c.x * matrix[column][0] + c.z * matrix[column][3];
        out[column][1] = c.y * matrix[column][1] + c.w * matrix[column][3];
    }
    return out;
}

glm::vec4 window_ndc_scale_offset(const FrameWindow& window) {
    return scale_offset(plan::PixelRect{0, 0, window.full_width_px, window.full_height_px}, window.rect);
}

} // namespace render
