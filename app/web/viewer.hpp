// The page's viewer: the showcase drawn by the same render::Renderer as
// `frustum-demo render` and `frustum-demo window`, into the browser's
// WebGL 2 canvas, from the same session (render::Session) and with the
// window command's frame step (window::FrameStep) without GLFW: input
// arrives as gl::InputEvent values (browser_input.hpp), the step's
// controls turn them into a window::ViewerState, and a frame is
// drawn only when something changed (the CPU rasterizers of headless
// browsers are slow). No printing: errors come back as frustum::Status.
#pragma once

#include <frustum/result.hpp>
#include <gl/web_context.hpp>
#include <gl/window_input.hpp>
#include <plan/effect.hpp>
#include <render/session.hpp>
#include <window/frame_painter.hpp>
#include <window/frame_step.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace web {

struct ViewerOptions {
    std::string scene_path;             // a glTF file in the page's embedded file system
    std::string canvas = "#canvas";     // CSS selector of the WebGL 2 canvas
    plan::Effect effect = plan::Effect::Plain;
    int width_px = 640, height_px = 360; // the canvas at start-up: where a derived mirror is placed
    std::function<void(std::string_view)> note; // where the mirror went (render::Session::open()); may be empty
};

class Viewer {
public:
    // The session every frustum-demo command opens (render::Session::open():
    // the scene, its main camera, the effect values resolved for it with
    // the mirror placed, the WebGL 2 context, the renderer), then the frame
    // painter. Errors come from scene::load_gltf(), gl::WebGlContext::create(),
    // gl::Functions::load() and render::Renderer::create() unchanged.
    static frustum::Result<std::unique_ptr<Viewer>> create(const ViewerOptions& options);

    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    // Queued until the next draw_if_changed().
    void push(const gl::InputEvent& event) { events_.push_back(event); }

    // Applies the queued events (the window's frame step, window::FrameStep)
    // and, when they (or the canvas size, read here) changed what is shown,
    // draws one frame into the canvas at width_px x height_px (its
    // drawing-buffer size). True when it drew.
    frustum::Result<bool> draw_if_changed(int width_px, int height_px);

    plan::Effect effect() const { return step_->state().effect; }
    const gl::ContextInfo& context_info() const { return session_.context->describe(); }

private:
    Viewer() = default;

    // Destroyed in reverse: the painter and the step, then the session
    // (its renderer, the table its objects point to, the context).
    render::Session session_;
    std::optional<window::FrameStep> step_;
    std::optional<window::FramePainter> painter_;
    std::vector<gl::InputEvent> events_;
    int width_px_ = 0;
    int height_px_ = 0;
    bool buttons_down_ = false; // cursor moves change nothing otherwise
    bool dirty_ = true;         // the next draw_if_changed() draws
};

} // namespace web
