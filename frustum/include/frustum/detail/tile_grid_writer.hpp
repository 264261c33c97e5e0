// How the library fills a TileGrid (crop_tiles, lens_tiles): the layout
// (edges at floor(i W / n)), sized arrays to write the tiles into,
// and the vector-of-Tile form the older API returns.
#pragma once

#include "frustum/crop.hpp"

namespace frustum::detail {

// Every pixel edge 0..count of `count` tiles across `size` pixels into
// edges[]: edge i is floor(i size / count), found by carrying the remainder
// (two integer divisions in all, not one per edge).
inline void tile_edges(int size, int count, int* edges) {
    const int step = size / count, extra = size % count;
    int edge = 0, remainder = 0;
    edges[0] = 0;
    for (int i = 1; i <= count; ++i) {
        edge += step;
        remainder += extra;
        if (remainder >= count) {
            remainder -= count;
            ++edge;
        }
        edges[i] = edge;
    }
}

struct TileGridWriter {
    // The grid's layout and traits; matrices and inverses sized (contents
    // left to the caller, who writes every tile).
    template <class T>
    static void layout(TileGrid<T>& grid, int width_px, int height_px, int columns, int rows, unsigned traits) {
        grid.columns_ = columns;
        grid.rows_ = rows;
        grid.traits_ = traits;
        grid.column_edges_px_.resize(static_cast<std::size_t>(columns) + 1);
        grid.row_edges_px_.resize(static_cast<std::size_t>(rows) + 1);
        tile_edges(width_px, columns, grid.column_edges_px_.data());
        tile_edges(height_px, rows, grid.row_edges_px_.data());
        const std::size_t tiles = static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
        grid.matrices_.resize(tiles);
        grid.inverses_.resize(tiles);
    }
    // An empty grid (after an error: nothing half-written is left in it).
    template <class T>
    static void clear(TileGrid<T>& grid) {
        grid.columns_ = grid.rows_ = 0;
        grid.column_edges_px_.clear();
        grid.row_edges_px_.clear();
        grid.matrices_.clear();
        grid.inverses_.clear();
    }
    template <class T>
    static Mat4<T>* matrices(TileGrid<T>& grid) {
        return grid.matrices_.data();
    }
    template <class T>
    static Mat4<T>* inverses(TileGrid<T>& grid) {
        return grid.inverses_.data();
    }
    // `count` vectors of working storage kept with the grid.
    template <class T>
    static Vec4<T>* scratch(TileGrid<T>& grid, std::size_t count) {
        grid.scratch_.resize(count);
        return grid.scratch_.data();
    }
    template <class T>
    static void set_traits(TileGrid<T>& grid, unsigned traits) {
        grid.traits_ = traits;
    }
};

// Tile i of a grid, converted where it is needed: emplace_back of one
// builds the Tile straight in a vector's storage (C++17 guaranteed elision,
// no temporary Tile copied in).
template <class T>
struct TileOf {
    const TileGrid<T>& grid;
    std::size_t i;
    operator Tile<T>() const { return grid.tile(i); } // NOLINT: implicit by design (emplace_back)
};

// Every tile of the grid, in index order.
template <class T>
std::vector<Tile<T>> tiles_of(const TileGrid<T>& grid) {
    std::vector<Tile<T>> tiles;
    tiles.reserve(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
        tiles.emplace_back(TileOf<T>{grid, i});
    }
    return tiles;
}

} // namespace frustum::detail
