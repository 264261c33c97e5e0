// A mirror for every scene (docs/any-scene.md). A scene with a node named
// "mirror" keeps it unless the command line places one by hand; a scene
// without one gets a floor mirror under its bounding box, as three.js's
// webgl_mirror example does. The placed mirror is a quad mesh and instance
// added to the scene (so every effect, the plain frame included, sees it);
// world_bounds stay those of the model. Pure: no GL.
#pragma once

#include <frustum/matrix_pair.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <string>

namespace plan {

// --mirror-plane / --mirror-rect (at most one is set; the parser checks
// that the plane's normal and the rectangle's sides are not degenerate).
struct MirrorRequest {
    std::optional<glm::vec4> plane; // a x + b y + c z + d = 0, reflecting towards (a, b, c)
    // centre c, first side a, second side b (full lengths, world units);
    // reflects towards a x b.
    std::optional<std::array<float, 9>> rect;
};

// Gives `scene` the mirror `request` asks for and says where it went, e.g.
// "mirror: floor under the model, y = -0.51, 2.6 x 2.6 (the scene has no node named mirror)";
// empty when the scene's own mirror is kept. With the frame's `camera`
// (perspective), a derived mirror whose floor would not be seen (the eye
// inside the bounds, or the floor covering under kMinFloorInView of the
// frame) stands in front of the eye instead, facing it: at the anchor A of
// view_anchor() (view_links.hpp), s_x wide and s_y high (the middle half of
// the frame each way), its sides along R and R x f.
std::optional<std::string> place_mirror(scene::Scene& scene, const MirrorRequest& request,
                                        const frustum::MatrixPair<float>* camera = nullptr);

// The floor mirror counts as seen when it covers this fraction of the frame
// (rays through a 16 x 9 grid of the near plane, occlusion not counted).
inline constexpr float kMinFloorInView = 0.05f;

// The fraction of `camera`'s frame (its 16 x 9 grid of rays) that hits the
// rectangle `mirror` in front of the eye; 0 without a perspective eye.
float fraction_in_view(const frustum::MatrixPair<float>& camera, const scene::MirrorRect& mirror);

// Adds a double-sided quad [-0.5, 0.5]^2 in the local XY plane, facing +Z
// (as a node named "mirror" has it, scene.hpp), with its own material of
// `color` and one instance at `world`; returns the instance's index. The
// placed mirror and the portal / recursion links (view_links.hpp) are these.
int add_quad_instance(scene::Scene& scene, const glm::mat4& world, const glm::vec4& color, const std::string& name);

} // namespace plan
