// One window frame as data: which effect, from which camera, with which
// render options, plus the inset and the help text. Pure: no GL.
#pragma once

#include "window/controls.hpp"
#include "window/orbit_camera.hpp"

#include <frustum/result.hpp>
#include <gl/window_framebuffer.hpp>
#include <plan/camera.hpp>
#include <plan/effect.hpp>
#include <render/renderer.hpp>
#include <plan/stereo.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace window {

struct Frame {
    Frame(plan::Effect frame_effect, plan::Cameras frame_cameras)
        : effect(frame_effect), cameras(std::move(frame_cameras)) {}

    plan::Effect effect = plan::Effect::Plain;
    plan::Cameras cameras;         // main: the camera this frame is drawn from
    render::RenderOptions options; // width_px / height_px: the framebuffer
    bool inset = false;
    std::vector<std::string> text; // help panel lines; empty: none
    // Set: cameras and options are one eye's (half the framebuffer's
    // width); the painter draws each eye's pair (plan/stereo.hpp) into
    // its half, and the inset over the right eye.
    std::optional<plan::StereoRig> stereo;
};

// The frame `state` asks for on a width_px x height_px framebuffer:
// cameras.main is scene_cameras.main exactly while state.orbit is unset,
// else the orbit's pair at the framebuffer's aspect; the effect values are
// the state's, the tile counts and the lens grid capped at one pixel per
// tile of this framebuffer (it changes with the window; the values given stay).
frustum::Result<Frame> make_frame(const ViewerState& state, const plan::Cameras& scene_cameras,
                                  const OrbitProjection& projection, const scene::Bounds& bounds, int width_px,
                                  int height_px);

// The effect the inset shows: the frustum view, or the plain camera view
// while the main view is the frustum view.
plan::Effect inset_effect(plan::Effect main_effect);

// Where the inset goes: a third of the width with the framebuffer's
// aspect, 8 px from the top-right corner (room for a 2 px border). Empty
// when the framebuffer is smaller than 96 x 64 px.
std::optional<gl::WindowRect> inset_rect(int width_px, int height_px);

} // namespace window
