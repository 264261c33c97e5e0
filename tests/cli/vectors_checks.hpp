// Properties every ok answer of frustum-vectors must have, checked with
// GLM alone (glm::inverse, plane algebra), independent of the library.
#pragma once

#include "vectors_support.hpp"

namespace vectors_test {

// `request_case` is the case as sent (for depth and points), `answer` the
// response case with ok: true. Checks: inverse = glm::inverse(matrix);
// w > 0 just inside the near face's centre; planes are unit, inward and
// equal to the normalized Gribb-Hartmann rows; corners, centre and
// vanishing points equal the canonical unprojections; each face's corners
// lie on its plane; the centre is inside when valid; clip = M [p, 1]; inside agrees
// with a clip-space test wherever the point is not within 1e-4 of a face.
void check_consistent(const json& request_case, const json& answer);

const DepthCase& depth_of(const json& request_case);

} // namespace vectors_test
