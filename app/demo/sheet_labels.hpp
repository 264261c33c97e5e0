// The contact sheet's captions: under each panel, the effect and its key
// parameters in stb_easy_font glyphs (window::layout_text(), the window
// overlay's layout, filled on the CPU here); the frustum panel's caption is
// its legend, in the line colours.
#pragma once

#include <image/image.hpp>
#include <plan/effect.hpp>
#include <render/renderer.hpp>

#include <frustum/matrix_pair.hpp>
#include <scene/scene.hpp>

#include <string>
#include <vector>

namespace demo {

struct CaptionLine {
    std::string text;
    image::Rgba color{235, 235, 235, 255};
};

// `picture` with a dark strip below holding `lines` (clipped to its width).
image::Image with_caption(const image::Image& picture, const std::vector<CaptionLine>& lines);

// What the panel of `effect` shows, e.g. {"nonaffine", "slit 1.2 m, pivot 3.6 m"}:
// the parameters as the renderer derives them for `camera` and `scene`.
std::vector<CaptionLine> effect_caption(plan::Effect effect, const render::RenderOptions& options,
                                        const std::string& camera_name, const frustum::MatrixPair<float>& camera,
                                        const scene::Scene& scene);

} // namespace demo
