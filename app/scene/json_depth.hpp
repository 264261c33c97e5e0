// A byte scan that bounds JSON nesting before any parser recurses into it
// (tinygltf converts "extras" recursively; deep input would overflow the stack).
#pragma once

#include <frustum/result.hpp>

#include <cstddef>

namespace scene::detail {

constexpr int kMaxJsonDepth = 64;

// Fails when arrays/objects nest deeper than `max_depth`. Brackets inside
// strings are skipped; the JSON is otherwise not validated here.
frustum::Status check_json_depth(const char* text, std::size_t size_bytes,
                                 int max_depth = kMaxJsonDepth);

} // namespace scene::detail
