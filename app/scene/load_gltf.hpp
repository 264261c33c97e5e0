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

struct LoadOptions {
    // Which glTF scene to flatten; absent: the file's default `scene`, or
    // scene 0 when the file names none. A file without any scenes yields
    // every root node.
    std::optional<int> scene_index;
    // Largest file accepted: the model itself and each file it references.
    std::uint64_t max_file_bytes = 256ull << 20;
    // Largest decoded image accepted, in pixels (width * height).
    std::uint64_t max_image_pixels = 8192ull * 8192ull;
};

frustum::Result<Scene> load_gltf(const std::string& path, const LoadOptions& options = {});

} // namespace scene
