// The glTF extensions the loader implements, and the check that refuses a
// file requiring any other one before tinygltf parses it (so a Draco file
// is named as such instead of failing deeper in the loader).
#pragma once

#include <frustum/result.hpp>

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace scene::detail {

inline constexpr const char* kUnlit = "KHR_materials_unlit";
inline constexpr const char* kTextureTransform = "KHR_texture_transform";
inline constexpr const char* kGpuInstancing = "EXT_mesh_gpu_instancing";

// In alphabetical order.
const std::vector<std::string>& supported_extensions();

// Every string of the root's extensionsRequired must be supported, e.g.
// "the file requires glTF extension KHR_draco_mesh_compression, which is not
// supported (supported: EXT_mesh_gpu_instancing, KHR_materials_unlit, KHR_texture_transform)".
frustum::Status check_required_extensions(const nlohmann::json& root);

} // namespace scene::detail
