// Cameras as view-projection pairs (DepthRange::ZeroToOne, the paper's
// range; DepthPolicy converts for the GPU): from the glTF cameras, or
// framing the scene when it has none.
#pragma once

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace render {

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
//   "render::find_camera(): no camera 'x'; the scene's cameras are: main, overview"
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
};

// main_camera: from find_camera() (-1: a framing camera from the front).
frustum::Result<Cameras> make_cameras(const scene::Scene& scene, int main_camera, int width_px, int height_px);

} // namespace render
