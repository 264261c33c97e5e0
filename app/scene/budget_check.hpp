// The load budget (scene::Budget) applied to a validated model, before
// build_scene() allocates anything that grows with the declared counts.
#pragma once

#include "scene/load_gltf.hpp"

#include <frustum/result.hpp>

#include <tiny_gltf.h>

#include <cstdint>
#include <string>

namespace scene::detail {

// "1.5 GiB", "320 MiB", "12 KiB", "100 B": for the budget's messages.
std::string format_bytes(std::uint64_t bytes);

// "... is over the budget of 1 GiB (raise it with --max-memory-mb)".
std::string over_memory_budget(const Budget& budget);

// Precondition: validate_model(model) passed. `decoded_image_bytes` is what
// the image loader already holds. Checks, in one O(nodes + primitives) walk
// of the whole node forest (every scene's trees are inside it): node and
// primitive counts, hierarchy depth, drawn vertices, and the bytes the
// vertex attributes and indices will decode to plus the images.
frustum::Status check_budget(const tinygltf::Model& model, const Budget& budget,
                             std::uint64_t decoded_image_bytes);

} // namespace scene::detail
