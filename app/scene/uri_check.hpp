// Pre-parse of the glTF JSON that rejects unusable JSON and every buffer or
// image uri that could name something outside the model's folder, with a
// message naming the uri (the sandbox in fs_sandbox.hpp is the second line).
#pragma once

#include <frustum/result.hpp>

#include "scene/load_gltf.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace scene::detail {

// Rule for one uri after percent-decoding; empty when acceptable. Accepts
// "data:...;base64,..." and relative paths to a file below the folder.
std::string uri_problem(const std::string& uri);

// Reads the JSON once as a stream of events (no tree is built, so memory
// stays O(nesting depth + longest string); call check_json_depth first) and
// checks that it is valid JSON, that the root is an object, that every
// extension in extensionsRequired is supported (extensions.hpp), that every
// buffers[i].uri and images[i].uri is acceptable, and that the tree tinygltf
// will build (values * kJsonValueBytes) fits budget.max_decoded_bytes and
// the "nodes" array budget.max_nodes (tinygltf spends ~1 KB and
// 20 us per node, so this is refused before it parses). Says what
// parse_model() must work around (JsonFacts).
struct JsonFacts {
    // The file has a skin without inverseBindMatrices or an animation channel
    // target without node: valid glTF 2.0 (identity matrices; a target named
    // by an extension such as KHR_animation_pointer) that tinygltf 2.7
    // refuses. Skins and animations are not drawn (load_gltf.hpp), so
    // parse_model() removes them before tinygltf reads the JSON.
    bool strip_skins_and_animations = false;
};

frustum::Result<JsonFacts> check_json_and_uris(const char* text, std::size_t size_bytes,
                                               const Budget& budget = {});

} // namespace scene::detail
