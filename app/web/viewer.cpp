#include "web/viewer.hpp"

#include <type_traits>
#include <utility>
#include <variant>

namespace web {
namespace {

// Does `event` change the picture? A cursor move only while a button is held.
bool changes_frame(const gl::InputEvent& event, bool& buttons_down) {
    if (const auto* button = std::get_if<gl::MouseButtonChanged>(&event)) {
        buttons_down = button->pressed;
        return false;
    }
    if (std::holds_alternative<gl::CursorMoved>(event)) {
        return buttons_down;
    }
    return true;
}

} // namespace

frustum::Result<std::unique_ptr<Viewer>> Viewer::create(const ViewerOptions& options) {
    std::unique_ptr<Viewer> viewer(new Viewer());
    // The scene's main camera, as `frustum-demo render` picks it without --camera,
    // and the effect values at their defaults, resolved for the scene.
    render::SessionSettings settings;
    settings.scene_path = options.scene_path;
    settings.width_px = options.width_px;
    settings.height_px = options.height_px;
    render::SessionHooks hooks;
    hooks.cameras_at_size = false; // the step makes them per canvas size
    hooks.refuse_explicit = false;
    hooks.note = options.note;
    hooks.make_context = [&options]() -> frustum::Result<std::unique_ptr<gl::Context>> {
        auto context = gl::WebGlContext::create(options.canvas, gl::ContextOptions{});
        if (!context) {
            return context.take_error();
        }
        return std::unique_ptr<gl::Context>(std::move(*context));
    };
    if (auto failure = viewer->session_.open(settings, plan::EffectParams{}, hooks)) {
        return frustum::Error{failure->message};
    }
    window::ViewerState state;
    static_cast<plan::EffectParams&>(state) = viewer->session_.effects.params;
    state.effect = options.effect;
    viewer->step_.emplace(viewer->session_, std::move(state));
    auto painter = window::FramePainter::create(*viewer->session_.fn);
    if (!painter) {
        return frustum::Error{painter.error()};
    }
    viewer->painter_.emplace(std::move(*painter));
    return viewer;
}

frustum::Result<bool> Viewer::draw_if_changed(int width_px, int height_px) {
    if (width_px != width_px_ || height_px != height_px_) {
        width_px_ = width_px;
        height_px_ = height_px;
        dirty_ = true;
    }
    if (width_px_ < 1 || height_px_ < 1) {
        events_.clear();
        return false;
    }
    if (auto input = step_->take_input(events_, width_px_, height_px_); !input) {
        return input.take_error();
    }
    for (const gl::InputEvent& event : events_) {
        dirty_ = changes_frame(event, buttons_down_) || dirty_;
    }
    events_.clear();
    // Escape closes the desktop window; a page stays open.
    step_->state().quit = false;
    if (!dirty_) {
        return false;
    }
    auto frame = step_->frame();
    if (!frame) {
        return frame.take_error();
    }
    if (auto painted = painter_->paint(*session_.renderer, *frame, width_px_, height_px_); !painted) {
        return frustum::Error{painted.error()};
    }
    dirty_ = false;
    return true;
}

} // namespace web
