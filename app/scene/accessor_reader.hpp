// Reads accessors of a model that passed validate_model(): dense data,
// zero fill when there is no bufferView, then sparse substitution.
#pragma once

#include <frustum/result.hpp>

#include <tiny_gltf.h>

#include <cstdint>
#include <vector>

namespace scene::detail {

// count * components floats; normalized integers mapped as the glTF spec
// says (unsigned: c / max, signed: max(c / max, -1)), others converted as is.
frustum::Result<std::vector<float>> read_floats(const tinygltf::Model& model, int accessor);

// A SCALAR accessor of unsigned integers, widened to 32 bits.
frustum::Result<std::vector<std::uint32_t>> read_uints(const tinygltf::Model& model, int accessor);

} // namespace scene::detail
