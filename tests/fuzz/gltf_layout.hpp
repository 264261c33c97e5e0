// The folder a fuzzed glTF file is loaded from (fuzz_gltf.cpp, and the
// robustness suite replaying tests/fuzz/regressions/gltf): the model at
// <root>/model/model.gltf and, next to it, files an input may reference by
// uri: tri.bin (Triangle.gltf's 44-byte buffer), sub/tri.bin, tex.png (2x2
// RGBA), folder.bin (a folder), pipe.bin (a FIFO: opening it for reading
// blocks, so a hang means the loader opened a non-regular file) and link.bin
// (a symlink to ../outside.bin). <root>/outside.bin is Triangle's buffer with
// first vertex x = kOutsideMarker: it must never show up in a loaded scene.
#pragma once

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>

namespace fuzz_layout {

inline constexpr float kOutsideMarker = 12345.0f;

inline const unsigned char kTriangle[44] = {0, 0, 1, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                            0, 0, 0, 0, 0, 0, 0, 0x80, 0x3f, 0, 0, 0, 0, 0, 0,
                                            0, 0, 0, 0, 0, 0, 0, 0, 0x80, 0x3f, 0, 0, 0, 0};

inline const unsigned char kPng2x2[73] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00,
    0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x06, 0x00, 0x00, 0x00, 0x72, 0xb6, 0x0d, 0x24, 0x00,
    0x00, 0x00, 0x10, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0xf0, 0x1f, 0x0a, 0x21,
    0x14, 0x00, 0x45, 0xcc, 0x07, 0xf9, 0x66, 0xcb, 0xff, 0x39, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e,
    0x44, 0xae, 0x42, 0x60, 0x82};

// False when a file could not be written.
inline bool write_file(const std::filesystem::path& path, const void* data, std::size_t size) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    return file.good();
}

// Lays the folder out below `root` (which must exist and be empty); returns
// the model path, or an empty string when something could not be created.
inline std::string make(const std::filesystem::path& root) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path model = root / "model";
    fs::create_directories(model / "sub", error);
    fs::create_directories(model / "folder.bin", error);
    unsigned char outside[sizeof kTriangle];
    std::copy(kTriangle, kTriangle + sizeof kTriangle, outside);
    std::memcpy(outside + 8, &kOutsideMarker, sizeof kOutsideMarker);
    const bool written = !error && write_file(model / "tri.bin", kTriangle, sizeof kTriangle) &&
                         write_file(model / "sub" / "tri.bin", kTriangle, sizeof kTriangle) &&
                         write_file(model / "tex.png", kPng2x2, sizeof kPng2x2) &&
                         write_file(root / "outside.bin", outside, sizeof outside);
    fs::create_symlink(root / "outside.bin", model / "link.bin", error);
    if (!written || error || ::mkfifo((model / "pipe.bin").c_str(), 0600) != 0) {
        return {};
    }
    return (model / "model.gltf").string();
}

} // namespace fuzz_layout
