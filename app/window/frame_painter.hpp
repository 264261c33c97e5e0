// Draws a window::Frame into the window's framebuffer 0 with the same
// renderer as `frustum-demo render`: the effect is rendered into an
// offscreen target of the framebuffer's size (render::Renderer::render_into)
// and blitted; the inset likewise at its own size into a corner. Stereo
// frames: each eye rendered and blitted into its half (left eye left), the
// inset over the right eye. Then frame.text, when it has lines, as the help
// panel on top (the web page's; the desktop window shows its help and
// control panel with window::ImGuiLayer instead and leaves frame.text empty).
#pragma once

#include "window/frame.hpp"
#include "window/text_overlay.hpp"

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/offscreen_target.hpp>
#include <render/renderer.hpp>

#include <optional>

namespace window {

class FramePainter {
public:
    static frustum::Result<FramePainter> create(const gl::Functions& fn);

    // The targets are kept between frames and made anew when the size changes.
    frustum::Status paint(const render::Renderer& renderer, const Frame& frame, int width_px, int height_px);

private:
    FramePainter(const gl::Functions& fn, TextOverlay text) : fn_(&fn), text_(std::move(text)) {}

    // `slot` holding a width x height target with gl::choose_samples(msaa_samples)
    // samples, made anew when its size or sample count differs.
    frustum::Result<const gl::OffscreenTarget*> sized(std::optional<gl::OffscreenTarget>& slot, int width_px,
                                                      int height_px, int msaa_samples);

    // frame.stereo: each eye into its half of framebuffer 0 (eye_target_ reused).
    frustum::Status paint_stereo(const render::Renderer& renderer, const Frame& frame, int width_px, int height_px);

    // frame.inset: the inset effect from frame.cameras into the top-right
    // corner of the width_px x height_px part of framebuffer 0 from x_px on.
    frustum::Status paint_inset(const render::Renderer& renderer, const Frame& frame, int x_px, int width_px,
                                int height_px);

    // The help panel on top of framebuffer 0, when frame.text has lines.
    frustum::Status draw_text(const render::Renderer& renderer, const Frame& frame, int width_px, int height_px);

    const gl::Functions* fn_;
    TextOverlay text_;
    std::optional<gl::OffscreenTarget> frame_target_;
    std::optional<gl::OffscreenTarget> inset_target_;
    std::optional<gl::OffscreenTarget> eye_target_;
};

} // namespace window
