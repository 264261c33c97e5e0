#include "window/frame_painter.hpp"

#include <gl/window_framebuffer.hpp>

#include <utility>

namespace window {
namespace {

constexpr int kInsetBorderPx = 2;
constexpr float kInsetBorderColor[4] = {0.95f, 0.95f, 0.95f, 1.0f};

} // namespace

frustum::Result<FramePainter> FramePainter::create(const gl::Functions& fn) {
    auto text = TextOverlay::create(fn);
    if (!text) {
        return text.take_error();
    }
    return FramePainter(fn, std::move(*text));
}

frustum::Result<const gl::OffscreenTarget*> FramePainter::sized(std::optional<gl::OffscreenTarget>& slot,
                                                                int width_px, int height_px, int msaa_samples) {
    auto samples = gl::choose_samples(*fn_, msaa_samples);
    if (!samples) {
        return frustum::Error{"window::FramePainter::paint(): " + samples.error()};
    }
    if (!slot || slot->width() != width_px || slot->height() != height_px || slot->samples() != *samples) {
        slot.reset(); // free the old one first
        auto target = gl::OffscreenTarget::create(
            *fn_, {width_px, height_px, gl::ColorStorage::Renderbuffer, gl::DepthFormat::Depth24, *samples});
        if (!target) {
            return frustum::Error{"window::FramePainter::paint(): " + target.error()};
        }
        slot = std::move(*target);
    }
    return &*slot;
}

frustum::Status FramePainter::paint_stereo(const render::Renderer& renderer, const Frame& frame, int width_px,
                                           int height_px) {
    auto eyes = plan::stereo_cameras(frame.cameras, *frame.stereo);
    if (!eyes) {
        return frustum::Error{eyes.error()};
    }
    const int eye_width_px = width_px / 2;
    auto target = sized(eye_target_, eye_width_px, height_px, frame.options.msaa_samples);
    if (!target) {
        return frustum::Error{target.error()};
    }
    constexpr float kBlack[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    gl::clear_window_rect(*fn_, {0, 0, width_px, height_px}, kBlack); // an odd width's last column
    const std::pair<const plan::Cameras*, int> sides[] = {{&eyes->left, 0}, {&eyes->right, eye_width_px}};
    for (const auto& [cameras, x_px] : sides) {
        if (auto status = renderer.render_into(frame.effect, *cameras, frame.options, **target); !status) {
            return status;
        }
        if (auto status = gl::blit_to_window(*fn_, **target, {x_px, 0, eye_width_px, height_px}); !status) {
            return status;
        }
    }
    return {};
}

frustum::Status FramePainter::paint(const render::Renderer& renderer, const Frame& frame, int width_px,
                                    int height_px) {
    if (frame.stereo) {
        if (auto status = paint_stereo(renderer, frame, width_px, height_px); !status) {
            return status;
        }
        if (auto status = paint_inset(renderer, frame, width_px / 2, width_px / 2, height_px); !status) {
            return status; // the inset over the right eye
        }
        return draw_text(renderer, frame, width_px, height_px);
    }
    auto main = sized(frame_target_, width_px, height_px, frame.options.msaa_samples);
    if (!main) {
        return main.take_error();
    }
    if (auto status = renderer.render_into(frame.effect, frame.cameras, frame.options, **main); !status) {
        return status;
    }
    if (auto status = gl::blit_to_window(*fn_, **main, {0, 0, width_px, height_px}); !status) {
        return status;
    }
    if (auto status = paint_inset(renderer, frame, 0, width_px, height_px); !status) {
        return status;
    }
    return draw_text(renderer, frame, width_px, height_px);
}

frustum::Status FramePainter::paint_inset(const render::Renderer& renderer, const Frame& frame, int x_px,
                                          int width_px, int height_px) {
    if (auto rect = inset_rect(width_px, height_px); frame.inset && rect) {
        rect->x += x_px;
        auto inset = sized(inset_target_, rect->width, rect->height, frame.options.msaa_samples);
        if (!inset) {
            return inset.take_error();
        }
        render::RenderOptions inset_options = frame.options;
        inset_options.pass_end = nullptr; // the main view's passes only
        if (auto status = renderer.render_into(inset_effect(frame.effect), frame.cameras, inset_options, **inset);
            !status) {
            return status;
        }
        gl::clear_window_rect(*fn_, {rect->x - kInsetBorderPx, rect->y - kInsetBorderPx,
                                     rect->width + 2 * kInsetBorderPx, rect->height + 2 * kInsetBorderPx},
                              kInsetBorderColor);
        if (auto status = gl::blit_to_window(*fn_, **inset, *rect); !status) {
            return status;
        }
    }
    return {};
}

frustum::Status FramePainter::draw_text(const render::Renderer& renderer, const Frame& frame, int width_px,
                                        int height_px) {
    if (!frame.text.empty()) {
        fn_->BindFramebuffer(GL_FRAMEBUFFER, 0);
        fn_->Viewport(0, 0, width_px, height_px);
        return text_.draw(renderer.programs().line, renderer.gpu_depth_range(frame.options.depth), frame.text,
                          width_px, height_px);
    }
    return {};
}

} // namespace window
