#include "fs_sandbox.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>

namespace scene::detail {

namespace fs = std::filesystem;

namespace {

// True when `path` is `root` itself or lies below it (both canonical).
bool is_within(const fs::path& root, const fs::path& path) {
    auto mismatch = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
    return mismatch.first == root.end();
}

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

} // namespace

FsSandbox::FsSandbox(fs::path root, std::uint64_t max_file_bytes)
    : root_(std::move(root)), root_string_(root_.string()), max_file_bytes_(max_file_bytes) {}

frustum::Result<FsSandbox> FsSandbox::for_model(const std::string& model_path,
                                                std::uint64_t max_file_bytes) {
    if (model_path.empty()) {
        return frustum::Error{"the path is empty"};
    }
    std::error_code error;
    fs::path model = fs::weakly_canonical(fs::path(model_path), error);
    if (error) {
        return frustum::Error{"cannot resolve the path: " + error.message()};
    }
    return FsSandbox(model.parent_path(), max_file_bytes);
}

frustum::Result<fs::path> FsSandbox::resolve(const std::string& path) const {
    using frustum::Error;
    std::error_code error;
    fs::path resolved = fs::weakly_canonical(fs::path(path), error);
    if (error) {
        return Error{"cannot resolve " + quoted(path) + ": " + error.message()};
    }
    if (!is_within(root_, resolved)) {
        return Error{quoted(path) + " resolves to " + quoted(resolved.string()) +
                     ", outside the model folder " + quoted(root_string_)};
    }
    fs::file_status status = fs::status(resolved, error);
    if (!fs::exists(status)) {
        return Error{quoted(path) + " does not exist"};
    }
    if (!fs::is_regular_file(status)) {
        return Error{quoted(path) + " is not a regular file"};
    }
    std::uint64_t size_bytes = fs::file_size(resolved, error);
    if (error) {
        return Error{"cannot get the size of " + quoted(path) + ": " + error.message()};
    }
    if (size_bytes > max_file_bytes_) {
        return Error{quoted(path) + " has " + std::to_string(size_bytes) +
                     " bytes, more than the limit of " + std::to_string(max_file_bytes_)};
    }
    return resolved;
}

frustum::Result<std::vector<unsigned char>> FsSandbox::read(const std::string& path) const {
    frustum::Result<fs::path> resolved = resolve(path);
    if (!resolved) {
        return resolved.take_error();
    }
    // Opens the checked, symlink-free path rather than `path` itself.
    std::ifstream file(*resolved, std::ios::binary | std::ios::ate);
    if (!file) {
        return frustum::Error{"cannot open " + quoted(path)};
    }
    std::streamoff size_bytes = file.tellg();
    if (size_bytes < 0 || static_cast<std::uint64_t>(size_bytes) > max_file_bytes_) {
        return frustum::Error{"cannot read " + quoted(path) + " within the size limit of " +
                              std::to_string(max_file_bytes_) + " bytes"};
    }
    std::vector<unsigned char> bytes(static_cast<std::size_t>(size_bytes));
    file.seekg(0);
    file.read(reinterpret_cast<char*>(bytes.data()), size_bytes);
    if (file.gcount() != size_bytes) {
        return frustum::Error{"short read of " + quoted(path) + ": got " +
                              std::to_string(file.gcount()) + " of " +
                              std::to_string(size_bytes) + " bytes"};
    }
    return bytes;
}

tinygltf::FsCallbacks FsSandbox::callbacks() {
    tinygltf::FsCallbacks callbacks{};
    callbacks.FileExists = &FsSandbox::exists_cb;
    callbacks.ExpandFilePath = &FsSandbox::expand_cb;
    callbacks.ReadWholeFile = &FsSandbox::read_cb;
    callbacks.WriteWholeFile = nullptr; // loading never writes
    callbacks.user_data = this;
    return callbacks;
}

// tinygltf probes "<base dir>/<uri>" and then "./<uri>"; only the first
// refusal is kept since it names the path the file actually asked for.
bool FsSandbox::exists_cb(const std::string& path, void* self) {
    auto* sandbox = static_cast<FsSandbox*>(self);
    frustum::Result<fs::path> resolved = sandbox->resolve(path);
    if (!resolved && sandbox->first_refusal_.empty()) {
        sandbox->first_refusal_ = resolved.error();
    }
    return resolved.ok();
}

// No "~" or environment expansion (tinygltf's default runs wordexp).
std::string FsSandbox::expand_cb(const std::string& path, void*) { return path; }

bool FsSandbox::read_cb(std::vector<unsigned char>* out, std::string* err,
                        const std::string& path, void* self) {
    auto* sandbox = static_cast<FsSandbox*>(self);
    frustum::Result<std::vector<unsigned char>> bytes = sandbox->read(path);
    if (!bytes) {
        if (sandbox->first_refusal_.empty()) {
            sandbox->first_refusal_ = bytes.error();
        }
        if (err) {
            *err += bytes.error();
        }
        return false;
    }
    *out = std::move(bytes).value();
    return true;
}

} // namespace scene::detail
