// Paper §5.5: a frustum is valid when its near face is a convex quadrilateral
// that separates the origin (eye) from the body (far corners).
//
// Taken literally this rejects many obliquely clipped frustums, whose tilted
// far plane misses side edges in front of the eye (docs/errata.md erratum 14):
// validate before the clip; clip_oblique() checks the clip itself.
#pragma once

#include "frustum/matrix_pair.hpp"

#include <string>

namespace frustum {

struct Validation {
    bool near_quad_finite = false;  // C1..C4 are finite points
    bool near_quad_convex = false;  // and form a convex quadrilateral
    bool eye_behind_near = false;   // eye on the near plane's negative side
    bool far_corners_beyond = false; // C5..C8 in front of the eye, beyond the near plane
    bool valid() const { return near_quad_finite && near_quad_convex && eye_behind_near && far_corners_beyond; }
    // Empty when valid, else which test failed.
    std::string reason() const;
};

template <class T>
Validation validate(const MatrixPair<T>& pair);

} // namespace frustum
