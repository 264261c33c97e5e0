// Binary glTF container layout, checked before tinygltf sees the bytes
// (tinygltf 2.7.0 trusts the BIN chunk length by up to 8 bytes too much).
#pragma once

#include <frustum/result.hpp>

#include <cstddef>
#include <cstdint>

namespace scene::detail {

// True when the bytes start with the GLB magic "glTF".
bool has_glb_magic(const std::uint8_t* bytes, std::size_t size_bytes);

// Where the JSON chunk's payload is; the BIN chunk is left to tinygltf.
struct GlbJson {
    std::size_t offset = 0;
    std::size_t size_bytes = 0;
};

// Checks the 12-byte header (magic, version 2, total length equal to the
// file size) and every chunk (8-byte header inside the file, payload inside
// the file, 4-byte aligned length): JSON first, then at most one BIN chunk
// right after it, then only chunks of other types, which are ignored.
frustum::Result<GlbJson> check_glb(const std::uint8_t* bytes, std::size_t size_bytes);

} // namespace scene::detail
