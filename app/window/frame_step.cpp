#include "window/frame_step.hpp"

#include <algorithm>
#include <utility>

namespace window {

FrameStep::FrameStep(render::Session& session, ViewerState state)
    : session_(session), controls_(control_scene_), state_(std::move(state)) {
    derive_from_scene();
}

void FrameStep::derive_from_scene() {
    attachments_ = mirror_attachments(session_.scene);
    projection_ = orbit_projection(session_.scene, session_.camera_index);
    control_scene_ = window::control_scene(session_.scene);
    controls_ = Controls(control_scene_);
}

void FrameStep::scene_replaced() {
    derive_from_scene();
    state_.orbit.reset();
    state_.mirror = {};
    applied_pose_ = {};
    state_.link_moves = ViewerState{}.link_moves;
    cameras_.reset();
}

void FrameStep::camera_changed() {
    projection_ = orbit_projection(session_.scene, session_.camera_index);
    state_.orbit.reset();
}

frustum::Status FrameStep::take_input(const std::vector<gl::InputEvent>& events, int width_px, int height_px) {
    // Stereo: cameras, frame and options are one eye's, half the width.
    const int eye_width_px = state_.stereo ? std::max(1, width_px / 2) : width_px;
    if (eye_width_px != eye_width_px_ || height_px != height_px_) {
        cameras_.reset();
        eye_width_px_ = eye_width_px;
        height_px_ = height_px;
    }
    if (!cameras_) {
        auto made = plan::make_cameras(session_.scene, session_.camera_index, eye_width_px_, height_px_);
        if (!made) {
            return made.take_error();
        }
        cameras_ = std::move(*made);
    }
    for (const gl::InputEvent& event : events) {
        controls_.apply(event, cameras_->main.pair, state_);
    }
    return {};
}

frustum::Result<Frame> FrameStep::frame() {
    if (session_.scene.mirror && state_.mirror != applied_pose_) {
        if (auto moved = session_.renderer->move_mirror(mirror_motion(*session_.scene.mirror, state_.mirror),
                                                        attachments_);
            !moved) {
            return moved.take_error();
        }
        applied_pose_ = state_.mirror;
    }
    auto frame = make_frame(state_, *cameras_, projection_, session_.scene.world_bounds, eye_width_px_, height_px_);
    if (!frame) {
        return frame.take_error();
    }
    frame->stereo = plan::stereo_rig(state_, frame->cameras.main.pair, session_.scene);
    return frame;
}

frustum::Result<std::optional<Frame>> FrameStep::step(const std::vector<gl::InputEvent>& events, int width_px,
                                                      int height_px) {
    if (auto input = take_input(events, width_px, height_px); !input) {
        return input.take_error();
    }
    if (state_.quit) {
        return std::optional<Frame>();
    }
    auto made = frame();
    if (!made) {
        return made.take_error();
    }
    return std::optional<Frame>(std::move(*made));
}

} // namespace window
