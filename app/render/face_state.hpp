// Which triangles face front, and whether back faces are culled, per draw.
//
// A reflected view flips triangle winding on screen (docs/errata.md erratum 3:
// MatrixPair::flips_winding()), and so does a model matrix with a negative
// determinant (glTF 2.0, "Transformations": such a node reverses the winding
// order). Two flips cancel. glFrontFace(GL_CW) draws a flipped draw as
// authored; restore_face_state() goes back to GL's defaults afterwards.
#pragma once

#include <gl/functions.hpp>

namespace render {

// GL_CCW (glTF's front face) unless exactly one of the two flips applies.
GLenum front_face(bool view_flips_winding, bool model_flips_winding);

// glFrontFace(front_face(...)), and back-face culling unless double-sided.
void set_face_state(const gl::Functions& fn, bool double_sided, bool view_flips_winding,
                    bool model_flips_winding);

// GL's defaults: glFrontFace(GL_CCW), culling off.
void restore_face_state(const gl::Functions& fn);

} // namespace render
