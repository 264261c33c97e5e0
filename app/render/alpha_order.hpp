// glTF alphaMode in the passes: which primitives go in which group, the
// order of the blended ones, and the blend state.
//
// Every pass draws OPAQUE primitives first, then MASK ones (the ALPHA_MASK
// program variant discards below alphaCutoff), then BLEND ones back to
// front with depth writes off: a blended primitive is hidden by the opaque
// geometry in front of it and shows the geometry behind it. Sorting is per
// primitive by the depth of its bounding-box centre, which is exact for
// primitives that do not interpenetrate (glTF 2.0 leaves the rest to the
// renderer).
#pragma once

#include <frustum/matrix_pair.hpp>
#include <gl/functions.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

namespace render {

// The order in which the groups are drawn.
enum class AlphaGroup { Opaque = 0, Mask = 1, Blend = 2 };
AlphaGroup alpha_group(scene::AlphaMode mode);

// A depth that grows away from the camera: the clip w (the eye depth, up to
// a positive factor, for any perspective pair, also a cropped, reflected or
// obliquely clipped one, whose row 3 the operations keep), or for an affine
// pair (orthographic: w is constant) the clip depth z/w in the direction of
// the pair's depth range.
float view_depth(const frustum::MatrixPair<float>& camera, const glm::vec3& world);

// Premultiplied-free "over" on colour, alpha accumulated so that an opaque
// background stays opaque: glBlendFuncSeparate(SRC_ALPHA, ONE_MINUS_SRC_ALPHA,
// ONE, ONE_MINUS_SRC_ALPHA); depth test on, depth writes off.
void begin_blending(const gl::Functions& fn);
// Back to the frame state: blending off, depth writes on.
void end_blending(const gl::Functions& fn);

} // namespace render
