// Only the near and far planes of raw_planes() (the same rows, same bits),
// for the library's callers that need the depth extent and not the sides
// (lens_tiles, once per grid). Defined in queries.cpp, beside raw_planes().
#pragma once

#include "frustum/queries.hpp"

namespace frustum::detail {

template <class T>
struct DepthPlanes {
    Plane<T> near;
    std::optional<Plane<T>> far; // absent for an infinite far plane (erratum 9)
};

template <class T>
DepthPlanes<T> raw_depth_planes(const MatrixPair<T>& pair);

} // namespace frustum::detail
