// Paper §5.4: lens refraction in tile-based rendering. The image is split
// into tiles; each tile's corners on the refraction plane are moved by the
// lens law (eq. 34) and the tile is rendered through the frustum whose near
// plane is the refraction plane and whose side planes pass through the eye
// and the moved corners (§4's frustum, assembled per tile from the grid's
// shared corners and edges: the inverse from its key points, §3.2, the
// matrix from the planes through them; detail/lens_tile_assembly.hpp). Inside the
// lens radius the moved quads shrink (magnification), outside they grow
// (barrel distortion). Shared corners move alike, so tiles stay seamless.
#pragma once

#include "frustum/crop.hpp"
#include "frustum/matrix_pair.hpp"
#include "frustum/queries.hpp"
#include "frustum/result.hpp"

#include <vector>

namespace frustum {

// A lens on the refraction plane, which is the camera's near plane. Its
// coordinates are metres in that plane, origin at the centre of the near
// rectangle, x towards its right edge, y towards its top edge.
template <class T>
struct Lens {
    Vec2<T> center_m{T(0)}; // C
    T radius_m = T(1);      // R > 0
    T power = T(2);         // p > 0; p > 1 magnifies inside R, p < 1 shrinks
};

// eq. 34: v = X - C, r = |v| / R, X' = C + R r^p v / |v| (X' = C at C).
template <class T>
Vec2<T> lens_warp(const Vec2<T>& point_m, const Lens<T>& lens);

// near_plane_frame() (the refraction plane's frame) is in queries.hpp.

// Tiles of a width_px x height_px image in the crop_tiles() layout, each
// with its lens frustum. Far plane of a tile: the nearest that keeps its four
// corner rays inside up to the camera's far distance, so nothing the camera
// sees is cut off. A tile whose moved corners are not a parallelogram has
// clip w varying over its near face; its far plane then pivots about the
// line where w = 0 meets the near plane, and on the other edges it lies
// beyond the far distance or never crosses them in front of the eye. Such
// tiles render correctly but fail the literal §5.5 test (far corners
// behind the eye): the limitation of affine frustums that §6 addresses (the camera must be perspective with a finite
// far plane, without an oblique near plane).
// The grid form writes into `out` (reusing its storage; left empty on an error).
template <class T>
Status lens_tiles(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px, int height_px, int columns,
                  int rows, TileGrid<T>& out);
template <class T>
Result<std::vector<Tile<T>>> lens_tiles(const MatrixPair<T>& camera, const Lens<T>& lens, int width_px,
                                        int height_px, int columns, int rows);

} // namespace frustum
