// Sizes and names for glTF accessor component types and element types.
#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <string>

namespace scene::detail {

// Bytes per component for the six glTF accessor component types, else 0.
std::size_t component_size_bytes(int component_type);
// Components per element: SCALAR 1, VEC2..VEC4, MAT2 4, MAT3 9, MAT4 16; else 0.
std::size_t components_per_element(int type);
// Bytes one element occupies, including the column padding glTF requires
// for 1- and 2-byte MAT2/MAT3 components (each column starts 4-aligned).
std::size_t element_size_bytes(int component_type, int type);

// "5126 (FLOAT)", "VEC3": for messages.
std::string component_type_name(int component_type);
std::string type_name(int type);

// "accessor 3 (POSITION of mesh 0 primitive 0)": the accessor and its first
// use by a mesh primitive, or just "accessor 3" when no primitive uses it.
std::string accessor_label(const tinygltf::Model& model, int accessor);

} // namespace scene::detail
