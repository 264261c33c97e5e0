// Shared helpers for the scene suite: temp folders, model paths, JSON
// mutation, base64 and GLB packing. Test-only code.
#pragma once

#include "support/temp_dir.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace scene_test {

using Json = nlohmann::json;
using Bytes = std::vector<std::uint8_t>;

std::string model_path(const std::string& name); // "box.gltf" -> tests/data/gltf-models/box.gltf
std::string showcase_path();

Bytes read_bytes(const std::filesystem::path& path);
void write_bytes(const std::filesystem::path& path, const Bytes& bytes);
void write_text(const std::filesystem::path& path, const std::string& text);
Json read_json(const std::filesystem::path& path);

Bytes base64_decode(const std::string& text);
std::string base64_encode(const Bytes& bytes);

// Buffer 0 of a glTF whose buffer is a base64 data uri: get and replace.
Bytes buffer0(const Json& gltf);
void set_buffer0(Json& gltf, const Bytes& bytes);
// Moves image 0 from a data uri into a new bufferView of buffer 0.
void image0_into_buffer_view(Json& gltf);

// A .glb: JSON chunk (buffer 0 without uri, holding `bin`) + BIN chunk.
Bytes make_glb(Json gltf, const Bytes& bin);

// A fresh, empty model folder in a support::TempDir, removed on scope exit
// (with a sibling "outside" folder for escape tests).
class TempDir {
public:
    TempDir();
    const std::filesystem::path& path() const { return model_dir_; }
    const std::filesystem::path& outside() const { return outside_dir_; }

private:
    support::TempDir root_;
    std::filesystem::path model_dir_;
    std::filesystem::path outside_dir_;
};

} // namespace scene_test
