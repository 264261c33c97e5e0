#include "demo/scene_files.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace demo {
namespace {

namespace fs = std::filesystem;

bool is_scene_file(const fs::directory_entry& entry) {
    std::error_code ignored;
    const fs::path extension = entry.path().extension();
    return (extension == ".gltf" || extension == ".glb") && entry.is_regular_file(ignored);
}

// The scene files directly in `folder`.
void add_scene_files(const fs::path& folder, std::vector<std::string>& files) {
    std::error_code error;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        if (is_scene_file(*it)) {
            files.push_back(it->path().string());
        }
    }
}

} // namespace

std::vector<std::string> scene_files_beside(const std::string& scene_path) {
    const fs::path folder = fs::path(scene_path).parent_path();
    const fs::path here = folder.empty() ? fs::path(".") : folder;
    std::vector<std::string> files;
    add_scene_files(here, files);
    // The folders next to it: the parent's subfolders (not the parent
    // itself), named as the scene's folder is (relative stays relative).
    const fs::path parent = (here / "..").lexically_normal();
    std::error_code error;
    for (fs::directory_iterator it(parent, error), end; !error && it != end; it.increment(error)) {
        std::error_code ignored;
        if (it->is_directory(ignored) && !fs::equivalent(it->path(), here, ignored)) {
            add_scene_files(it->path(), files);
        }
    }
    std::sort(files.begin(), files.end());
    files.erase(std::unique(files.begin(), files.end()), files.end());
    if (files.size() > kMaxSceneFiles) {
        files.resize(kMaxSceneFiles);
    }
    return files;
}

} // namespace demo
