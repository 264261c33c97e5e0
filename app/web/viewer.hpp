// The page's viewer: the showcase drawn by the same render::Renderer as
// `frustum-demo render` and `frustum-demo window`, into the browser's
// WebGL 2 canvas. It is the window command's frame loop without GLFW:
// input arrives as gl::InputEvent values (browser_input.hpp), the
// window::Controls turn them into a window::ViewerState, and a frame is
// drawn only when something changed (the CPU rasterizers of headless
// browsers are slow). No printing: errors come back as frustum::Status.
#pragma once

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/web_context.hpp>
#include <gl/window_input.hpp>
#include <plan/camera.hpp>
#include <plan/effect.hpp>
#include <render/renderer.hpp>
#include <scene/scene.hpp>
#include <window/controls.hpp>
#include <window/frame_painter.hpp>
#include <window/mirror_pose.hpp>
#include <window/orbit_camera.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace web {

struct ViewerOptions {
    std::string scene_path;             // a glTF file in the page's embedded file system
    std::string canvas = "#canvas";     // CSS selector of the WebGL 2 canvas
    render::Effect effect = render::Effect::Plain;
};

class Viewer {
public:
    // Loads the scene, makes the WebGL 2 context and the renderer. Errors
    // come from scene::load_gltf(), gl::WebGlContext::create(),
    // gl::Functions::load() and render::Renderer::create() unchanged.
    static frustum::Result<std::unique_ptr<Viewer>> create(const ViewerOptions& options);

    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    // Queued until the next draw_if_changed().
    void push(const gl::InputEvent& event) { events_.push_back(event); }

    // Applies the queued events and, when they (or the canvas size, read
    // here) changed what is shown, draws one frame into the canvas at
    // width_px x height_px (its drawing-buffer size). True when it drew.
    frustum::Result<bool> draw_if_changed(int width_px, int height_px);

    render::Effect effect() const { return state_.effect; }
    const gl::ContextInfo& context_info() const { return context_->describe(); }

private:
    Viewer() = default;

    scene::Scene scene_;
    int camera_index_ = -1;
    std::vector<int> attachments_;
    window::OrbitProjection projection_;
    std::optional<window::Controls> controls_;
    window::ViewerState state_;
    window::MirrorPose applied_pose_;
    std::vector<gl::InputEvent> events_;
    int width_px_ = 0;
    int height_px_ = 0;
    bool buttons_down_ = false; // cursor moves change nothing otherwise
    bool dirty_ = true;         // the next draw_if_changed() draws
    std::optional<render::Cameras> cameras_;
    // Destroyed in reverse: painter and renderer, then the table their
    // objects point to, then the context.
    std::unique_ptr<gl::WebGlContext> context_;
    std::unique_ptr<gl::Functions> fn_;
    std::optional<render::Renderer> renderer_;
    std::optional<window::FramePainter> painter_;
};

} // namespace web
