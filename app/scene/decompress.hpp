// Compressed glTF data decoded into plain buffers, before validate_model()
// sees the model, so that every check and reader after it works on ordinary
// accessors: EXT_meshopt_compression bufferViews (decode_meshopt.cpp, into
// their place in the view's buffer) and KHR_draco_mesh_compression
// primitives (decode_draco.cpp, into a new buffer with one bufferView per
// decoded accessor). Whatever the decoders are given lies inside its buffer,
// the bytes they write are counted against budget.max_decoded_bytes before
// they are allocated, and decoded counts must equal the accessors' counts.
#pragma once

#include "scene/load_gltf.hpp"

#include <frustum/result.hpp>

#include <tiny_gltf.h>

namespace scene::detail {

// Runs validate_buffer_views() first (the compressed bytes must lie inside
// their buffers), then both decoders.
frustum::Status decompress(tinygltf::Model& model, const Budget& budget);

// decode_meshopt.cpp: every bufferView with EXT_meshopt_compression.
frustum::Status decode_meshopt(tinygltf::Model& model);

// decode_draco.cpp: every primitive with KHR_draco_mesh_compression; adds at
// most `max_bytes` of decoded data.
frustum::Status decode_draco(tinygltf::Model& model, std::uint64_t max_bytes);

// Extension members, for both decoders: a whole number >= 0 (`fallback`
// when absent, -1: required), or an error naming `where` and `key`.
frustum::Result<std::uint64_t> extension_count(const tinygltf::Value& object, const char* key,
                                               const std::string& where, long long fallback = -1);

} // namespace scene::detail
