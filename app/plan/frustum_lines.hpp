// A frustum as world-space line segments, read from its key points (paper
// §3.2: eq. 8 corners C1..C8 and centre D, eq. 7 eye O and vanishing points
// O1 = m1', O2 = m0'), with frustum::to_point deciding what is at infinity.
#pragma once

#include <frustum/matrix_pair.hpp>

#include <glm/glm.hpp>

#include <vector>

namespace plan {

struct FrustumLineStyle {
    float marker_size_m = 0.1f;     // the crosses at O, D, O1, O2
    float infinite_length_m = 50.0f; // how far an edge to a point at infinity is drawn
};

// Pairs of points for GL_LINES:
// - the 12 edges: near face C1-C2-C3-C4, far face C5-C6-C7-C8, sides Ci-Ci+4.
//   A side edge whose far corner is at or beyond infinity (w <= 0: an
//   infinite far plane, or the tilted far plane of an oblique near plane,
//   docs/errata.md erratum 8) is a ray from its near corner towards the point where
//   the edge crosses infinity, drawn infinite_length_m long;
// - when the eye O is finite: the 4 lines O-C1..O-C4 and a cross at O;
// - a cross at the centre D, and at O1 and O2 when they are finite.
std::vector<glm::vec3> frustum_lines(const frustum::MatrixPair<float>& pair, const FrustumLineStyle& style);

} // namespace plan
