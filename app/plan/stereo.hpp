// Stereo without GL: two eye pairs from one camera pair, as the
// generalized perspective of a shared virtual screen (Kooima 2008,
// frustum::screen_projection). The screen is the camera's own frustum
// cross-section at the convergence depth, so both eyes see exactly the
// camera's picture there (zero disparity) and each eye is its own pair:
// the mirror, lens and tile effects build their cameras from it as from
// any other camera (per-eye reflections, per-eye lens tiles).
#pragma once

#include "plan/camera.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>

namespace plan {

inline constexpr float kDefaultIpdM = 0.064f; // interpupillary distance, metres

struct StereoRig {
    float ipd_m = kDefaultIpdM;
    float convergence_m = 1.0f; // depth of the zero-disparity plane in front of the camera's eye
};

// The camera's frame, read from the pair's key points (§3.2, eq. 7-8):
// the eye, unit right / up / forward axes of its image, the near depth,
// the far depth (empty: infinite) and the screen rectangle at depth 1 m
// (corners lower left, lower right, upper left as offsets from the eye).
struct CameraFrame {
    glm::dvec3 eye, right, up, forward;
    double near_m = 0.0;
    std::optional<double> far_m;
    glm::dvec3 lower_left, lower_right, upper_left; // at depth 1 m, relative to eye
};

// Errors: a camera without a finite eye (orthographic), e.g.
// "plan::camera_frame(): stereo needs a perspective camera (finite eye)".
frustum::Result<CameraFrame> camera_frame(const frustum::MatrixPair<float>& camera);

struct StereoEyes {
    frustum::MatrixPair<float> left, right;
};

// Eyes at camera eye -/+ ipd/2 along the image's right axis, both through
// the camera's frustum cross-section at rig.convergence_m:
//   screen corners S = O + convergence_m * corner(1 m)
//   eye pair = screen_projection(S_ll, S_lr, S_ul, O -/+ ipd/2 right, near, far)
// with the camera's near and far depths and depth range. ipd_m = 0 gives
// the camera's pair back (to float rounding). Errors: the camera_frame()
// ones, ipd_m < 0 or not finite, convergence_m not between the near and
// the far depth, e.g. "plan::stereo_eyes(): convergence 0.05 m must be
// beyond the near plane (0.1 m) and before the far plane (100 m)".
frustum::Result<StereoEyes> stereo_eyes(const frustum::MatrixPair<float>& camera, const StereoRig& rig);

// Cameras for each eye: main becomes that eye's pair (named "<main>
// left" / "<main> right"), the overview stays. The main pair must be made
// for one eye's image (make_cameras() with width_px / 2).
struct StereoCameras {
    Cameras left, right;
};
frustum::Result<StereoCameras> stereo_cameras(const Cameras& cameras, const StereoRig& rig);

// A point's depth along the camera's forward axis (metres in front of its eye).
double depth_m(const CameraFrame& frame, const glm::dvec3& point);

// The horizontal disparity, right eye's x minus left eye's x in pixels of
// one eye's image (width_px wide), of a point at depth depth_m:
//   ipd (1 - convergence / depth) * width_px / (screen width at convergence)
// (similar triangles through the shared screen); zero on the convergence
// plane, positive (uncrossed) beyond it, negative in front of it.
double predicted_disparity_px(const CameraFrame& frame, const StereoRig& rig, double depth_m, int width_px);

// The default convergence depth: the mirror's centre when it lies in front
// of the camera, 1.5 x the near depth or more (a point on the mirror then
// has zero disparity and what it reflects appears behind it), else the
// centre of `bounds`, else twice the near depth.
float default_convergence_m(const frustum::MatrixPair<float>& camera, const std::optional<scene::MirrorRect>& mirror,
                            const scene::Bounds& bounds);

} // namespace plan
