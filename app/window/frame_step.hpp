// The frame step the desktop window (demo/window_run.cpp) and the web page
// (web/viewer.cpp) both run: input -> cameras -> controls -> mirror pose ->
// frame. What it keeps between frames (the controls, the viewer state, the
// cameras at the framebuffer's size, the mirror pose the renderer has) is
// here once; painting the frame (FramePainter), the panel, the swap and
// the title are each caller's own. No GL but the renderer's mirror move.
#pragma once

#include "window/controls.hpp"
#include "window/frame.hpp"
#include "window/mirror_pose.hpp"
#include "window/orbit_camera.hpp"

#include <frustum/result.hpp>
#include <gl/window_input.hpp>
#include <plan/camera.hpp>
#include <render/session.hpp>

#include <optional>
#include <vector>

namespace window {

class FrameStep {
public:
    // `session` (its scene, camera index and renderer) outlives the step;
    // `state`: what is shown first.
    FrameStep(render::Session& session, ViewerState state);

    // The session has another scene (a scene file the window's panel
    // opened): what is derived from it anew, its camera framed anew (the
    // orbit dropped), the mirror and the facing mirrors where it puts them.
    void scene_replaced();
    // The session has another camera index: its projection, the orbit dropped.
    void camera_changed();
    // The cameras are made anew at the next input (the framebuffer or --stereo changed).
    void reset_cameras() { cameras_.reset(); }

    // Input: `events` applied to the state, with the scene's cameras for a
    // width_px x height_px framebuffer (one eye's half of it with stereo),
    // made when missing or when the size changed.
    frustum::Status take_input(const std::vector<gl::InputEvent>& events, int width_px, int height_px);
    // The renderer's mirror moved to the state's pose, then the frame the
    // state asks for at the size of the last take_input(), with the stereo
    // rig its values ask for.
    frustum::Result<Frame> frame();
    // take_input(), then frame() unless the input asked to quit (empty then).
    frustum::Result<std::optional<Frame>> step(const std::vector<gl::InputEvent>& events, int width_px,
                                               int height_px);

    ViewerState& state() { return state_; }
    const ViewerState& state() const { return state_; }
    const ControlScene& control_scene() const { return control_scene_; }

private:
    void derive_from_scene();

    render::Session& session_;
    std::vector<int> attachments_;       // what moves with the mirror
    OrbitProjection projection_;         // the orbit camera's
    ControlScene control_scene_;
    Controls controls_;
    ViewerState state_;
    MirrorPose applied_pose_;            // where the renderer's mirror is
    std::optional<plan::Cameras> cameras_;
    int eye_width_px_ = 0;
    int height_px_ = 0;
};

} // namespace window
