// The scene files the window's panel offers beside the current one: every
// .gltf and .glb file in the scene's folder and in the folders next to it
// (one level: the vendored samples keep one sample per folder). Read from
// the file system each time the list is opened; no GL, nothing printed.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace demo {

inline constexpr std::size_t kMaxSceneFiles = 64;

// Paths (the folder's path joined with the file name) sorted, the current
// file among them, at most kMaxSceneFiles; a folder that cannot be read
// adds nothing (an empty list when nothing can).
std::vector<std::string> scene_files_beside(const std::string& scene_path);

} // namespace demo
