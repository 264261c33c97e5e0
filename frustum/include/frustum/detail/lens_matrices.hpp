// The matrices of lens_tiles() alone, built exactly as lens_tiles builds
// them (same corners, planes and far plane; same checks and error texts) but
// without their inverses: what the benchmark's baseline "build each tile's
// matrix, then invert it" starts from (tests/bench/bench_ops.cpp).
#pragma once

#include "frustum/lens.hpp"

#include <vector>

namespace frustum::detail {

// `layout` receives the tiles' layout (its pairs are crops, not lens
// frustums); matrices[layout.index(c, r)] is tile (c, r)'s matrix.
template <class T>
Status lens_tile_matrices(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px, int height_px,
                          int columns, int rows, TileGrid<T>& layout, std::vector<Mat4<T>>& matrices);

} // namespace frustum::detail
