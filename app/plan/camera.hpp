// Cameras as view-projection pairs (DepthRange::ZeroToOne, the paper's
// range; DepthPolicy converts for the GPU): from the glTF cameras, or
// framing the scene when it has none.
#pragma once

#include "plan/effect.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace plan {

// projection (frustum::perspective / orthographic) composed with the view.
// The view is the closed-form inverse of the rigid camera_to_world [R | t]:
// [R^T | -R^T t] (RigidTransform::from_rotation_translation), so nothing is
// inverted numerically. image_aspect (width / height of the image) replaces
// the camera's own aspect ratio, so nothing is stretched: a perspective
// camera keeps its yfov, an orthographic one its ymag (xmag becomes
// ymag * image_aspect). The window and `render` both come through here.
frustum::Result<frustum::MatrixPair<float>> camera_pair(const scene::Camera& camera, float image_aspect);

// A perspective camera, vertical field of view 45 degrees, looking at the
// centre of `bounds` from the direction `from_direction` (need not be unit,
// must not be parallel to +Y), just far enough that the bounding sphere
// fills the frame; near and far enclose the sphere. A box of zero size (one
// point) is framed as a sphere of radius 1 m.
frustum::Result<frustum::MatrixPair<float>> framing_camera(const scene::Bounds& bounds,
                                                           const glm::vec3& from_direction, float aspect);

// The index into scene.cameras that `selector` names: a camera's name, else
// its node's name, else a decimal index. Without a selector: the camera
// named "main", else camera 0; -1 when the scene has no cameras. Errors:
//   "plan::find_camera(): no camera 'x'; the scene's cameras are: main, overview"
frustum::Result<int> find_camera(const scene::Scene& scene, const std::optional<std::string>& selector);

struct NamedCamera {
    std::string name;
    frustum::MatrixPair<float> pair;
};

struct Cameras {
    NamedCamera main;
    // For the frustum view: the camera named "overview" when it is not the
    // main camera, else a framing camera that also takes in the main eye.
    NamedCamera overview;
    // Set when the file camera's far plane was replaced (derived_far_m()):
    // which far it had and which it got, for main to print.
    std::optional<std::string> far_note;
    // Set when main is orthographic: a perspective camera with its view
    // (perspective_twin()), which the effects that need a finite eye draw
    // with (cameras_for()), and what twin_note says about it.
    std::optional<NamedCamera> perspective_twin;
    std::optional<std::string> twin_note;
};

// A perspective camera that sees what the orthographic `camera` sees at the
// depth of the centre of `bounds`: the same axis and up, the framing
// cameras' vertical field of view (45 degrees), the eye on the axis at the
// distance where that field of view is 2 ymag high at the centre's depth
// (so the centre's plane looks the same); near and far enclose `bounds`
// (far 1.05 x the farthest corner, near the nearest corner's depth / 2,
// at least far / kMaxFarPerNear).
frustum::Result<frustum::MatrixPair<float>> perspective_twin(const scene::Camera& camera, const scene::Bounds& bounds,
                                                             float image_aspect);

// `cameras`, with main replaced by the perspective twin when `effect`
// needs a finite eye (effect_needs_finite_eye()) and main has a twin.
Cameras cameras_for(Effect effect, const Cameras& cameras);

// The largest far / near the effects take from a file camera
// (docs/any-scene.md, "Far planes"). A ZeroToOne perspective's far plane
// F = m3 - m2 has the normal length n / (f - n) of its rows' size, and the
// library reads it as absent (infinite, erratum 9) below 64 float epsilons
// of that size (frustum/src/queries.cpp): about 1.5e-5, f / n = 6.5e4. At
// the 2e7 of a CAD export (5e-8) it is below float's own step beside 1
// (6e-8) and rounds away. 1e4 keeps a factor 6.5 from the library's limit,
// and there n / (f - n) = 1e-4 is still good to 0.06% in float.
inline constexpr float kMaxFarPerNear = 1e4f;

// The far distance (m) the effects use for a file camera whose far plane is
// absent, or (perspective) more than kMaxFarPerNear times its near one:
// 1.05 times the distance from the eye to the farthest corner of `bounds`
// (the whole scene stays in front of it), at least 2 near, at most (for a
// perspective) kMaxFarPerNear near and the file's own far. Empty when the
// file's far plane is kept.
std::optional<float> derived_far_m(const scene::Camera& camera, const scene::Bounds& bounds);

// main_camera: from find_camera() (-1: a framing camera from the front). A
// file camera without a usable far plane gets derived_far_m()'s, and
// far_note says so.
frustum::Result<Cameras> make_cameras(const scene::Scene& scene, int main_camera, int width_px, int height_px);

} // namespace plan
