#include "web/viewer.hpp"

#include <plan/camera.hpp>
#include <scene/load_gltf.hpp>
#include <window/frame.hpp>
#include <plan/camera.hpp>

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
    auto scene = scene::load_gltf(options.scene_path);
    if (!scene) {
        return frustum::Error{scene.error()};
    }
    viewer->scene_ = std::move(*scene);
    // The scene's main camera, as `frustum-demo render` picks it without --camera.
    auto camera_index = render::find_camera(viewer->scene_, std::nullopt);
    if (!camera_index) {
        return frustum::Error{camera_index.error()};
    }
    viewer->camera_index_ = *camera_index;
    viewer->attachments_ = window::mirror_attachments(viewer->scene_);
    viewer->projection_ = window::orbit_projection(viewer->scene_, viewer->camera_index_);
    viewer->controls_.emplace(window::control_scene(viewer->scene_));
    viewer->state_.effect = options.effect;

    auto context = gl::WebGlContext::create(options.canvas, gl::ContextOptions{});
    if (!context) {
        return frustum::Error{context.error()};
    }
    viewer->context_ = std::move(*context);
    auto fn = gl::Functions::load(*viewer->context_);
    if (!fn) {
        return frustum::Error{fn.error()};
    }
    viewer->fn_ = std::make_unique<gl::Functions>(*fn);
    auto renderer = render::Renderer::create(*viewer->context_, *viewer->fn_, viewer->scene_);
    if (!renderer) {
        return frustum::Error{renderer.error()};
    }
    viewer->renderer_.emplace(std::move(*renderer));
    auto painter = window::FramePainter::create(*viewer->fn_);
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
        cameras_.reset();
        dirty_ = true;
    }
    if (width_px_ < 1 || height_px_ < 1) {
        events_.clear();
        return false;
    }
    if (!cameras_) {
        auto made = render::make_cameras(scene_, camera_index_, width_px_, height_px_);
        if (!made) {
            return frustum::Error{made.error()};
        }
        cameras_ = std::move(*made);
    }
    for (const gl::InputEvent& event : events_) {
        controls_->apply(event, cameras_->main.pair, state_);
        dirty_ = changes_frame(event, buttons_down_) || dirty_;
    }
    events_.clear();
    // Escape closes the desktop window; a page stays open.
    state_.quit = false;
    if (!dirty_) {
        return false;
    }
    if (scene_.mirror && state_.mirror != applied_pose_) {
        if (auto moved = renderer_->move_mirror(window::mirror_motion(*scene_.mirror, state_.mirror), attachments_);
            !moved) {
            return frustum::Error{moved.error()};
        }
        applied_pose_ = state_.mirror;
    }
    auto frame = window::make_frame(state_, *cameras_, projection_, scene_.world_bounds, width_px_, height_px_);
    if (!frame) {
        return frustum::Error{frame.error()};
    }
    if (auto painted = painter_->paint(*renderer_, *frame, width_px_, height_px_); !painted) {
        return frustum::Error{painted.error()};
    }
    dirty_ = false;
    return true;
}

} // namespace web
