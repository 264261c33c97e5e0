// Effect parameters that fit any scene (docs/any-scene.md): what the
// command line leaves unset is derived from the scene's bounds and the
// camera of the frame, so a default never fails; what it sets is checked
// against this camera with a one-line error naming the option, its value
// and the range that would work. Pure: no GL.
#pragma once

#include "plan/curved_mirror.hpp"
#include "plan/non_affine_frustum.hpp"

#include <frustum/lens.hpp>
#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>

namespace plan {

// Explicit effect parameters (RenderOptions::fit); unset = derived.
struct EffectFit {
    std::optional<float> slit_m;            // --slit: nonaffine slit depth in front of the eye
    std::optional<float> pivot_m;           // --pivot: depth where the slit planes cut the side planes
    std::optional<glm::vec2> lens_center;   // --lens-center: in the frame, [-1, 1]^2 (x right, y up)
    std::optional<float> lens_radius;       // --lens-radius: fraction of the frame's half height, (0, 1]
};

// The non-affine options for `camera`: base with slit_depth_m and
// pivot_depth_m replaced by the fit. Derived: pivot = depth of the bounds'
// centre, clamped to [1.05 near, 0.95 far]; slit = pivot / 3.
// Errors (explicit values only) name the option and the valid range, e.g.
// "--pivot 9 must be less than the far distance 3.99 m of this camera".
frustum::Result<NonAffineOptions> fit_non_affine(const frustum::MatrixPair<float>& camera,
                                                 const scene::Bounds& bounds, const NonAffineOptions& base,
                                                 const EffectFit& fit);

// The lens on `camera`'s near plane. Without --lens-center / --lens-radius
// the scene's lens spot (node "lens") when it is in front of the camera,
// else: centre = the bounds' centre as seen on the near plane, kept within
// the middle 60% of the frame; radius = half the bounds' radius as seen
// there, within 10%..40% of the frame's half height.
frustum::Result<frustum::Lens<float>> fit_lens(const frustum::MatrixPair<float>& camera,
                                               const std::optional<scene::LensSpot>& spot,
                                               const scene::Bounds& bounds, const EffectFit& fit, float power);

// The largest sagitta CurvedMirror::create() accepts for `mirror` and
// `shape`: half the distance d from the centre to the rim.
float max_sagitta_m(const scene::MirrorRect& mirror, CapShape shape);

// The curved mirror's default sagitta: d / 5 (a fifth of the distance from
// the mirror's centre to its rim), and at most a quarter of how far the
// model (`model_bounds`) reaches in front of the mirror's plane, so that a
// bulging floor mirror under a small model does not swallow it.
float fit_sagitta_m(const scene::MirrorRect& mirror, CapShape shape, const scene::Bounds& model_bounds);

} // namespace plan
