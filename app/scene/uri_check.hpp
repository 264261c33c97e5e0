// Pre-parse of the glTF JSON that rejects unusable JSON and every buffer or
// image uri that could name something outside the model's folder, with a
// message naming the uri (the sandbox in fs_sandbox.hpp is the second line).
#pragma once

#include <frustum/result.hpp>

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
// buffers[i].uri and images[i].uri is acceptable, and that the tree tinygltf
// will build (values * kJsonValueBytes) fits `max_tree_bytes`; `budget_note`
// ends that message (" of the budget ... (raise it with --max-memory-mb)").
frustum::Status check_json_and_uris(const char* text, std::size_t size_bytes,
                                    std::uint64_t max_tree_bytes = UINT64_MAX,
                                    const std::string& budget_note = {});

} // namespace scene::detail
