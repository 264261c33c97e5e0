// Text as triangles, from stb_easy_font (libstb-dev's stb_easy_font.h: the
// glyphs are built from small quads, so no font asset or texture is
// needed). Pure: no GL.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace window {

// stb_easy_font's advance from one line to the next, in font dots.
inline constexpr float kLineHeightDots = 12.0f;

struct TextLayout {
    // Glyph triangles (3 vertices each), in framebuffer pixels with the
    // origin at the bottom-left, as glViewport counts; z = 0.
    std::vector<glm::vec3> triangles;
    glm::vec2 size_px{0.0f}; // width and height of the text block
};

// `lines` top to bottom, starting at `top_left_px` (pixels from the
// framebuffer's top-left corner, y down). A '\t' in a line starts a second
// column, aligned for all lines after the widest first column. scale:
// pixels per font dot (> 0); framebuffer_height_px turns y around.
TextLayout layout_text(const std::vector<std::string>& lines, glm::vec2 top_left_px, float scale,
                       int framebuffer_height_px);

} // namespace window
