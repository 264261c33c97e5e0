// The scenes the "any scene" tests walk, shared by the scene, plan, gl and
// window suites:
// - scene_files(): the showcase, then every model the project generates in
//   tests/data/gltf-models (scripts/make_feature_gltf.py), sorted; always
//   there, a missing one is a broken checkout.
// - corpus_folder(name): a third-party corpus (gltf-samples,
//   gltf-validator-corpus) under the folder FRUSTUM_TEST_DATA names (the
//   CMake option of that name sets it for every test). Not part of the
//   repository: when it is not set, the corpus checks are a skip
//   (tests/skips.hpp), never a pass.
#pragma once

#include "skips.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace test_samples {

// Every .gltf and .glb below `root`, sorted.
inline std::vector<std::filesystem::path> gltf_files_under(const std::filesystem::path& root) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        const auto extension = entry.path().extension();
        if (entry.is_regular_file() && (extension == ".gltf" || extension == ".glb")) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

inline std::filesystem::path models_folder() {
    return std::filesystem::path(FRUSTUM_SOURCE_DIR) / "tests/data/gltf-models";
}

// A generated model by file name ("box.gltf").
inline std::string model_path(const std::string& name) { return (models_folder() / name).string(); }

inline std::vector<std::filesystem::path> scene_files() {
    std::vector<std::filesystem::path> files{std::filesystem::path(FRUSTUM_SOURCE_DIR) / "assets/showcase.gltf"};
    const std::filesystem::path root = models_folder();
    REQUIRE_MESSAGE(std::filesystem::is_directory(root), "no generated models folder " << root.string());
    const auto models = gltf_files_under(root);
    files.insert(files.end(), models.begin(), models.end());
    REQUIRE(files.size() >= 20); // the showcase and the 19 generated models
    return files;
}

// FRUSTUM_TEST_DATA/name, or nothing after a skip that says what to set.
inline std::optional<std::filesystem::path> corpus_folder(const std::string& name) {
    const char* data = std::getenv("FRUSTUM_TEST_DATA");
    if (data == nullptr || *data == '\0') {
        test_skips::skip("set FRUSTUM_TEST_DATA (cmake -DFRUSTUM_TEST_DATA=DIR) to a folder holding " +
                         name + "/");
        return std::nullopt;
    }
    const std::filesystem::path folder = std::filesystem::path(data) / name;
    // Named but not there: a mistake, not a skip.
    REQUIRE_MESSAGE(std::filesystem::is_directory(folder),
                    "FRUSTUM_TEST_DATA is " << data << ", which has no folder " << name << "/");
    return folder;
}

} // namespace test_samples
