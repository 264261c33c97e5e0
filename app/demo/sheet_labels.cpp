#include "demo/sheet_labels.hpp"

#include <plan/number_text.hpp>
#include <plan/scene_fit.hpp>
#include <window/text_layout.hpp>

#include <algorithm>
#include <cmath>

namespace demo {
namespace {

constexpr int kPaddingPx = 3;
constexpr image::Rgba kStripColor{32, 32, 36, 255};
constexpr image::Rgba kYellow{255, 217, 26, 255};  // render's main frustum colour
constexpr image::Rgba kMagenta{230, 26, 230, 255}; // render's reflection frustum colour

// Fills the glyph triangles of one line; stb_easy_font's glyphs are
// axis-aligned quads, so each pair of triangles fills its bounding box.
void fill_text(image::Image& image, const std::string& text, int top_px, image::Rgba color) {
    const window::TextLayout layout =
        window::layout_text({text}, glm::vec2(kPaddingPx, static_cast<float>(top_px)), 1.0f, image.height);
    for (std::size_t q = 0; q + 6 <= layout.triangles.size(); q += 6) {
        glm::vec2 low(layout.triangles[q]), high(layout.triangles[q]);
        for (std::size_t k = q; k < q + 6; ++k) {
            low = glm::min(low, glm::vec2(layout.triangles[k]));
            high = glm::max(high, glm::vec2(layout.triangles[k]));
        }
        // Bottom-left pixel coordinates back to rows from the top.
        for (int y = static_cast<int>(std::lround(low.y)); y < static_cast<int>(std::lround(high.y)); ++y) {
            for (int x = static_cast<int>(std::lround(low.x)); x < static_cast<int>(std::lround(high.x)); ++x) {
                const int row = image.height - 1 - y;
                if (x >= 0 && x < image.width && row >= 0 && row < image.height) {
                    image::set_pixel(image, x, row, color);
                }
            }
        }
    }
}

} // namespace

image::Image with_caption(const image::Image& picture, const std::vector<CaptionLine>& lines) {
    const int strip_px = static_cast<int>(lines.size()) * static_cast<int>(window::kLineHeightDots) + 2 * kPaddingPx;
    image::Image out = image::make_image(picture.width, picture.height + strip_px, kStripColor);
    std::copy(picture.rgba.begin(), picture.rgba.end(), out.rgba.begin());
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const int top_px = picture.height + kPaddingPx + static_cast<int>(i) * static_cast<int>(window::kLineHeightDots);
        fill_text(out, lines[i].text, top_px, lines[i].color);
    }
    return out;
}

std::vector<CaptionLine> effect_caption(plan::Effect effect, const render::RenderOptions& o,
                                        const std::string& camera_name, const frustum::MatrixPair<float>& camera,
                                        const scene::Scene& scene) {
    using plan::number_text;
    const std::string name(plan::to_string(effect));
    switch (effect) {
    case plan::Effect::Plain:
        return {{name + ", from " + camera_name}};
    case plan::Effect::Mirror:
        return {{name + ", " + std::string(plan::to_string(o.mirror_method))}};
    case plan::Effect::Tiles:
        return {{name + " " + std::to_string(o.tile_columns) + "x" + std::to_string(o.tile_rows) +
                 (o.tile_borders ? ", borders" : "")}};
    case plan::Effect::Frustum:
        return {{name + " (" + std::string(plan::to_string(o.mirror_method)) + ")"},
                {"yellow: camera", kYellow},
                {"magenta: mirror camera", kMagenta}};
    case plan::Effect::Curved:
        return {{name + " " + std::string(plan::to_string(o.curved.shape)) + " " + std::to_string(o.curved.patches) +
                 "x" + std::to_string(o.curved.patches)},
                {"sagitta " + number_text(o.curved.sagitta_m) + " m"}};
    case plan::Effect::Lens: {
        std::vector<CaptionLine> lines{{name + " " + std::to_string(o.lens_grid) + "x" + std::to_string(o.lens_grid) +
                                        ", p " + number_text(o.lens_power)}};
        const auto frame = frustum::near_plane_frame(camera);
        const auto lens = plan::fit_lens(camera, scene.lens, scene.world_bounds, o.fit, o.lens_power);
        if (frame && lens) {
            // The centre in the frame's half sizes (scale 1): a float zero prints as 0.
            lines.push_back({"at " + number_text(lens->center_m.x / frame->half_width_m, 1.0) + "," +
                             number_text(lens->center_m.y / frame->half_height_m, 1.0) + " r " +
                             number_text(lens->radius_m / frame->half_height_m)});
        }
        return lines;
    }
    case plan::Effect::NonAffine: {
        std::vector<CaptionLine> lines{{name}};
        if (const auto fitted = plan::fit_non_affine(camera, scene.world_bounds, o.nonaffine, o.fit)) {
            lines.push_back({"slit " + number_text(fitted->slit_depth_m) + " m, pivot " +
                             number_text(fitted->pivot_depth_m) + " m"});
        }
        return lines;
    }
    case plan::Effect::Portal:
        return {{name + ": the scene from the exit, through the entry"}};
    case plan::Effect::Recursion:
        return {{name + " " + std::string(plan::to_string(o.recursion_links)) + ", depth " +
                 std::to_string(o.recursion_depth)}};
    }
    return {{name}};
}

} // namespace demo
