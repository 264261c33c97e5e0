// File access for one model: only regular files inside the model's folder,
// each at most a given size. Also the tinygltf FsCallbacks that enforce it.
#pragma once

#include <frustum/result.hpp>

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace scene::detail {

class FsSandbox {
public:
    // The sandbox root is the folder holding `model_path` (symlinks resolved).
    static frustum::Result<FsSandbox> for_model(const std::string& model_path,
                                                std::uint64_t max_file_bytes);

    const std::string& root() const { return root_string_; }

    // Reads `path` if it is a regular file inside root() and small enough.
    frustum::Result<std::vector<unsigned char>> read(const std::string& path) const;

    // Callbacks for tinygltf::TinyGLTF::SetFsCallbacks. `this` is their
    // user_data: the sandbox must outlive the parse and must not move.
    tinygltf::FsCallbacks callbacks();

    // Why the first path tinygltf asked for was refused; empty if none was.
    const std::string& first_refusal() const { return first_refusal_; }

private:
    FsSandbox(std::filesystem::path root, std::uint64_t max_file_bytes);
    // The resolved path when `path` may be read, else the reason it may not.
    frustum::Result<std::filesystem::path> resolve(const std::string& path) const;

    static bool exists_cb(const std::string& path, void* self);
    static std::string expand_cb(const std::string& path, void* self);
    static bool read_cb(std::vector<unsigned char>* out, std::string* err,
                        const std::string& path, void* self);

    std::filesystem::path root_;
    std::string root_string_;
    std::uint64_t max_file_bytes_;
    std::string first_refusal_;
};

} // namespace scene::detail
