#include "window/text_layout.hpp"

// A system header (-isystem /usr/include): its static functions, unused
// here, do not warn.
#include <stb/stb_easy_font.h>

#include <algorithm>

namespace window {
namespace {

constexpr float kColumnGapDots = 12.0f;

// stb_easy_font's vertex: x, y, z, then RGBA8 (ignored: the overlay sets the colour).
struct EasyFontVertex {
    float x, y, z;
    unsigned char rgba[4];
};
static_assert(sizeof(EasyFontVertex) == 16, "stb_easy_font writes 16-byte vertices");

float width_dots(std::string text) {
    return text.empty() ? 0.0f : static_cast<float>(stb_easy_font_width(text.data()));
}

// Appends the glyphs of `text` at (x, y) dots as triangles, mapped to pixels by `to_px`.
template <class ToPixels>
void append_glyphs(std::string text, float x, float y, const ToPixels& to_px, std::vector<glm::vec3>& out) {
    if (text.empty()) {
        return;
    }
    // stb_easy_font's documentation: about 270 bytes (4 quads) per character
    // on average; room for 16 quads each, so no glyph is cut off.
    std::vector<EasyFontVertex> quads(text.size() * 64);
    const int quad_count = stb_easy_font_print(x, y, text.data(), nullptr, quads.data(),
                                               static_cast<int>(quads.size() * sizeof(EasyFontVertex)));
    for (int q = 0; q < quad_count; ++q) {
        const EasyFontVertex* v = &quads[static_cast<std::size_t>(q) * 4];
        for (int corner : {0, 1, 2, 0, 2, 3}) {
            out.push_back(to_px(v[corner].x, v[corner].y));
        }
    }
}

} // namespace

TextLayout layout_text(const std::vector<std::string>& lines, glm::vec2 top_left_px, float scale,
                       int framebuffer_height_px) {
    const auto to_px = [&](float x_dots, float y_dots) {
        return glm::vec3(top_left_px.x + x_dots * scale,
                         static_cast<float>(framebuffer_height_px) - (top_left_px.y + y_dots * scale), 0.0f);
    };
    float first_column_dots = 0.0f;
    for (const std::string& line : lines) {
        const std::size_t tab = line.find('\t');
        if (tab != std::string::npos) {
            first_column_dots = std::max(first_column_dots, width_dots(line.substr(0, tab)));
        }
    }
    const float second_column_dots = first_column_dots + kColumnGapDots;
    TextLayout layout;
    float width = 0.0f;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        const float y = static_cast<float>(i) * kLineHeightDots;
        const std::size_t tab = line.find('\t');
        append_glyphs(line.substr(0, tab), 0.0f, y, to_px, layout.triangles);
        if (tab == std::string::npos) {
            width = std::max(width, width_dots(line));
        } else {
            const std::string second = line.substr(tab + 1);
            append_glyphs(second, second_column_dots, y, to_px, layout.triangles);
            width = std::max(width, second_column_dots + width_dots(second));
        }
    }
    layout.size_px = glm::vec2(width, static_cast<float>(lines.size()) * kLineHeightDots) * scale;
    return layout;
}

} // namespace window
