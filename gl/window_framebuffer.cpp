#include "gl/window_framebuffer.hpp"

#include "gl/errors.hpp"

#include <algorithm>
#include <string>

namespace gl {

frustum::Status blit_to_window(const Functions& fn, const OffscreenTarget& source, const WindowRect& destination) {
    const bool same_size = destination.width == source.width() && destination.height == source.height();
    source.resolve();
    fn.BindFramebuffer(GL_READ_FRAMEBUFFER, source.resolved_framebuffer().id());
    fn.ReadBuffer(GL_COLOR_ATTACHMENT0);
    fn.BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    fn.Disable(GL_SCISSOR_TEST);
    fn.BlitFramebuffer(0, 0, source.width(), source.height(), destination.x, destination.y,
                       destination.x + destination.width, destination.y + destination.height, GL_COLOR_BUFFER_BIT,
                       same_size ? GL_NEAREST : GL_LINEAR);
    fn.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return check_error(fn, "gl::blit_to_window(): glBlitFramebuffer");
}

void clear_window_rect(const Functions& fn, const WindowRect& rect, const float (&rgba)[4]) {
    fn.BindFramebuffer(GL_FRAMEBUFFER, 0);
    fn.Enable(GL_SCISSOR_TEST);
    fn.Scissor(rect.x, rect.y, rect.width, rect.height);
    fn.ClearColor(rgba[0], rgba[1], rgba[2], rgba[3]);
    fn.Clear(GL_COLOR_BUFFER_BIT);
    fn.Disable(GL_SCISSOR_TEST);
}

frustum::Result<image::Image> read_window_pixels(const Functions& fn, int width_px, int height_px) {
    if (width_px < 1 || height_px < 1) {
        return frustum::Error{"gl::read_window_pixels(): width and height must be >= 1, got " +
                              std::to_string(width_px) + "x" + std::to_string(height_px)};
    }
    fn.BindFramebuffer(GL_FRAMEBUFFER, 0);
    fn.ReadBuffer(GL_BACK);
    fn.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    fn.PixelStorei(GL_PACK_ALIGNMENT, 1);
    fn.PixelStorei(GL_PACK_ROW_LENGTH, 0);
    fn.PixelStorei(GL_PACK_SKIP_PIXELS, 0);
    fn.PixelStorei(GL_PACK_SKIP_ROWS, 0);
    image::Image result = image::make_image(width_px, height_px, {0, 0, 0, 255});
    fn.ReadPixels(0, 0, width_px, height_px, GL_RGBA, GL_UNSIGNED_BYTE, result.rgba.data());
    if (auto error = check_error(fn, "gl::read_window_pixels(): glReadPixels"); !error) {
        return frustum::Error{error.error()};
    }
    // GL's rows start at the bottom.
    const auto row_bytes = static_cast<std::ptrdiff_t>(width_px) * 4;
    for (int top = 0, bottom = height_px - 1; top < bottom; ++top, --bottom) {
        std::swap_ranges(result.rgba.begin() + top * row_bytes, result.rgba.begin() + (top + 1) * row_bytes,
                         result.rgba.begin() + bottom * row_bytes);
    }
    for (std::size_t alpha = 3; alpha < result.rgba.size(); alpha += 4) {
        result.rgba[alpha] = 255;
    }
    return result;
}

} // namespace gl
