// Random, well-conditioned mirror and crop cases shared by the speed and
// accuracy benchmarks: rotated views, off-axis frustums, mirrors facing the
// eye. Built in double; benchmarks cast to float.
#pragma once

#include <frustum/frustum.hpp>

#include <cstdint>
#include <vector>

namespace bench {

struct MirrorCase {
    frustum::MatrixPair<double> camera;   // P V
    frustum::Plane<double> mirror_plane;  // the real eye is on its positive side
    frustum::Rectangle<double> rectangle; // a mirror rectangle in that plane
    glm::dvec3 eye;
};

// `count` cases in the given depth range; each camera/mirror pair passes
// frustum::mirror() in double (cases it rejects are redrawn).
std::vector<MirrorCase> make_mirror_cases(int count, frustum::DepthRange depth, std::uint32_t seed);

} // namespace bench
