// Structural checks on a parsed tinygltf model. After validate_model() passes,
// every index used by build_scene is in range and every accessor's bytes lie
// inside its bufferView and buffer, so reading needs no further range checks
// except on values read from the file (index values, sparse indices).
#pragma once

#include <frustum/result.hpp>

#include <tiny_gltf.h>

namespace scene::detail {

// Runs all of the checks below, in this order.
frustum::Status validate_model(const tinygltf::Model& model);

// validate_accessors.cpp: bufferView ranges and strides, then accessors
// (component type, count, normalized, byte range, alignment, sparse parts).
frustum::Status validate_buffer_views(const tinygltf::Model& model);
frustum::Status validate_accessors(const tinygltf::Model& model);

// validate_meshes.cpp: primitive modes, attribute formats and counts,
// index accessors, material indices, morph-target accessor indices.
frustum::Status validate_meshes(const tinygltf::Model& model);

// validate.cpp: asset.version (major 2; minVersion at most 2.0).
frustum::Status validate_asset(const tinygltf::Model& model);

// validate_morphs.cpp: morph targets' POSITION/NORMAL (VEC3 FLOAT, one per
// vertex), the same target count in every primitive of a mesh, and
// mesh.weights / node.weights (one finite weight per target).
frustum::Status validate_morphs(const tinygltf::Model& model);

// validate_instancing.cpp: EXT_mesh_gpu_instancing on a node with a mesh,
// TRANSLATION/ROTATION/SCALE accessors in range, of the allowed formats,
// all with the same count >= 1.
frustum::Status validate_instancing(const tinygltf::Model& model);

// validate.cpp: images (decoded size), textures and material texture
// indices. (extensionsRequired is checked before parsing: extensions.hpp.)
frustum::Status validate_images_textures_materials(const tinygltf::Model& model);

// validate_nodes.cpp: node indices and TRS/matrix sizes, the node forest
// (no cycles, one parent each), scenes, and camera parameters.
frustum::Status validate_nodes(const tinygltf::Model& model);
frustum::Status validate_scenes(const tinygltf::Model& model);
frustum::Status validate_cameras(const tinygltf::Model& model);

} // namespace scene::detail
