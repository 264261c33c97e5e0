// The scenes every "any scene" test walks: the showcase, then every glTF
// of the vendored samples (tests/data/gltf-samples, FRUSTUM_SAMPLES_DIR),
// sorted. Shared by the gl and window suites.
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace test_samples {

inline std::vector<std::filesystem::path> scene_files() {
    std::vector<std::filesystem::path> files{std::filesystem::path(FRUSTUM_SOURCE_DIR) / "assets/showcase.gltf"};
    const std::filesystem::path root(FRUSTUM_SAMPLES_DIR);
    // The samples are part of the repository: a missing folder is a broken checkout.
    REQUIRE_MESSAGE(std::filesystem::is_directory(root), "no samples folder " << root.string());
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        const auto extension = entry.path().extension();
        if (entry.is_regular_file() && (extension == ".gltf" || extension == ".glb")) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin() + 1, files.end());
    REQUIRE(files.size() >= 19); // the showcase and the 18 samples
    return files;
}

} // namespace test_samples
