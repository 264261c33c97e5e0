// The window's default framebuffer (0): copying an offscreen frame into it
// and reading it back (screenshots). Works for any context with a visible
// surface; the offscreen backends have none.
#pragma once

#include "gl/functions.hpp"
#include "gl/offscreen_target.hpp"

#include <frustum/result.hpp>
#include <image/image.hpp>

namespace gl {

// Pixels from the bottom-left corner, as glViewport counts them.
struct WindowRect {
    int x = 0, y = 0, width = 0, height = 0;
};

// glBlitFramebuffer of all of `source` onto `destination` of framebuffer 0
// (GL_NEAREST when the sizes match, else GL_LINEAR). Leaves framebuffer 0
// bound for drawing and reading.
frustum::Status blit_to_window(const Functions& fn, const OffscreenTarget& source, const WindowRect& destination);

// Clears `rect` of framebuffer 0 to `rgba` (scissored; the scissor test is
// off afterwards).
void clear_window_rect(const Functions& fn, const WindowRect& rect, const float (&rgba)[4]);

// The back buffer of framebuffer 0 (call before swapping), rows top to
// bottom, alpha forced to 255 as the window shows it (opaque).
frustum::Result<image::Image> read_window_pixels(const Functions& fn, int width_px, int height_px);

} // namespace gl
