// from_planes(planes, far_points, depth) with the far points in an array
// (lens_tiles passes a tile's four without building a vector per tile), and
// the same construction's matrix alone: what "build the tile's matrix, then
// invert it" starts from (the lens_tiles baseline of tests/bench/bench_ops).
// Same checks and error texts as from_planes.
#pragma once

#include "frustum/from_planes.hpp"

#include <cstddef>

namespace frustum::detail {

template <class T>
Result<MatrixPair<T>> from_planes_points(const SidePlanes<T>& planes, const Vec3<T>* far_points, std::size_t count,
                                         DepthRange depth);

template <class T>
Result<Mat4<T>> from_planes_matrix(const SidePlanes<T>& planes, const Vec3<T>* far_points, std::size_t count,
                                   DepthRange depth);

} // namespace frustum::detail
