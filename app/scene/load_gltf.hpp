// glTF 2.0 (.gltf or .glb) -> validated scene::Scene. No GL, no printing.
//
// What is loaded: meshes (all seven primitive modes, indexed or not),
// POSITION, NORMAL, COLOR_0, TEXCOORD_0 (sparse accessors applied), the base
// colour factor and texture (decoded to RGBA8), double-sidedness, the node
// forest of one scene flattened to world transforms, cameras, and the special
// nodes "mirror" and "lens" (see scene.hpp).
// What is ignored: skins, morph targets and animations (meshes are drawn in
// their static bind pose with the nodes' own transforms), samplers, every
// material input other than the base colour, attributes other than the four
// above (they are still range-checked), and extensions.
//
// Safety: the whole file is checked before anything is used (GLB chunk
// layout, JSON nesting depth, every index, byte range, stride, component type
// and camera parameter). Files referenced by uri are read only from inside the
// model's folder (no "..", no absolute paths, no symlinks leading out, no
// directories), each at most LoadOptions::max_file_bytes. On failure nothing
// is returned but the error, which names the file and the broken rule with
// its values:
//   "scene::load_gltf(): /m/a.gltf: accessor 3 (POSITION of mesh 0 primitive
//    0) reads bytes [0, 480) of bufferView 1 which has 240 bytes"
#pragma once

#include "scene/scene.hpp"

#include <frustum/result.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace scene {

// What one load may cost, checked before anything large is allocated: an
// input that exceeds a limit is refused with a one-line error naming the
// value, the limit and the frustum-demo option that raises it. The defaults
// fit a phone (docs/robustness.md lists them with the measured costs).
struct Budget {
    // Decoded bytes the scene may hold: vertex attributes as loaded (POSITION
    // and NORMAL 12 B, TEXCOORD_0 8 B, COLOR_0 16 B per vertex), indices 4 B
    // each, RGBA8 images, and the parsed JSON (kJsonValueBytes per value).
    // A render's peak memory is about 5x this (GPU copies, llvmpipe).
    std::uint64_t max_decoded_bytes = 256ull << 20; // --max-memory-mb
    // Nodes in the file (counted in the JSON before tinygltf parses it:
    // it spends about 1 KB and 20 us per node), and mesh primitives.
    std::uint64_t max_nodes = 100000; // --max-nodes
    // Longest parent-to-child chain (a root alone has depth 1).
    std::uint64_t max_depth = 10000; // --max-depth
    // Vertices drawn per frame: over every node with a mesh, the index
    // count (or vertex count) of each of its primitives.
    std::uint64_t max_drawn_vertices = 1ull << 25; // --max-drawn-vertices
};

// Bytes one parsed JSON value costs (nlohmann's tree for the uri check is not
// built; tinygltf's tree and its Value copies of extras are), measured.
inline constexpr std::uint64_t kJsonValueBytes = 160;

struct LoadOptions {
    // Which glTF scene to flatten; absent: the file's default `scene`, or
    // scene 0 when the file names none. A file without any scenes yields
    // every root node.
    std::optional<int> scene_index;
    // Largest file accepted: the model itself and each file it references.
    std::uint64_t max_file_bytes = 256ull << 20;
    // Largest decoded image accepted, in pixels (width * height).
    std::uint64_t max_image_pixels = 8192ull * 8192ull;
    Budget budget;
};

frustum::Result<Scene> load_gltf(const std::string& path, const LoadOptions& options = {});

} // namespace scene
