// Pre-parse of the glTF JSON that rejects unusable JSON and every buffer or
// image uri that could name something outside the model's folder, with a
// message naming the uri (the sandbox in fs_sandbox.hpp is the second line).
#pragma once

#include <frustum/result.hpp>

#include <cstddef>
#include <string>

namespace scene::detail {

// Rule for one uri after percent-decoding; empty when acceptable. Accepts
// "data:...;base64,..." and relative paths to a file below the folder.
std::string uri_problem(const std::string& uri);

// Parses the JSON (call check_json_depth first) and checks that the root is an
// object, that every extension in extensionsRequired is supported
// (extensions.hpp) and that every buffers[i].uri and images[i].uri is acceptable.
frustum::Status check_json_and_uris(const char* text, std::size_t size_bytes);

} // namespace scene::detail
