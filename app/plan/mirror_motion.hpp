// Moving a planar mirror as a rigid body (the window's mirror keys): the
// check that a transform is rigid, and the mirror rectangle it carries.
#pragma once

#include <frustum/result.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

namespace plan {

// Ok when `motion` is a rotation plus a translation: orthonormal upper 3x3
// with determinant +1 (a reflection would turn the mirror's back to the
// front) and last row (0, 0, 0, 1), each within 1e-4. Otherwise
// "<where>: motion must be rigid (det 1, orthonormal columns, last row 0 0 0 1), got det=8 ...".
frustum::Status check_rigid_motion(const glm::mat4& motion, const char* where);

// The rectangle moved by `motion`: corner as a point, a1 and a2 as
// vectors; the surface instance index is kept.
scene::MirrorRect moved_mirror(const scene::MirrorRect& mirror, const glm::mat4& motion);

} // namespace plan
