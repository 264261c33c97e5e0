// The glTF extensions the loader implements, and the check that refuses a
// file requiring any other one before tinygltf parses it (so such a file is
// named as such instead of failing deeper in the loader).
#pragma once

#include <frustum/result.hpp>

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace scene::detail {

inline constexpr const char* kUnlit = "KHR_materials_unlit";
inline constexpr const char* kTextureTransform = "KHR_texture_transform";
inline constexpr const char* kGpuInstancing = "EXT_mesh_gpu_instancing";
// Integer POSITION/NORMAL/TANGENT/TEXCOORD formats (validate_meshes.cpp;
// accessor_reader.cpp maps them to floats, the node transform dequantizes).
inline constexpr const char* kMeshQuantization = "KHR_mesh_quantization";
// Compressed primitives and bufferViews, decoded into plain accessors before
// validation (decompress.hpp).
inline constexpr const char* kDraco = "KHR_draco_mesh_compression";
inline constexpr const char* kMeshopt = "EXT_meshopt_compression";

// In alphabetical order.
const std::vector<std::string>& supported_extensions();

// Every string of the root's extensionsRequired must be supported, e.g.
// "the file requires glTF extension KHR_materials_variants, which is not
// supported (supported: EXT_mesh_gpu_instancing, EXT_meshopt_compression,
// KHR_draco_mesh_compression, KHR_materials_unlit, KHR_mesh_quantization, KHR_texture_transform)".
frustum::Status check_required_extensions(const nlohmann::json& root);

} // namespace scene::detail
