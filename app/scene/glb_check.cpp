#include "glb_check.hpp"

#include <cstring>
#include <string>

namespace scene::detail {

namespace {

constexpr std::size_t kHeaderBytes = 12;
constexpr std::size_t kChunkHeaderBytes = 8;
constexpr std::uint32_t kChunkJson = 0x4E4F534A; // "JSON" little-endian
constexpr std::uint32_t kChunkBin = 0x004E4942;  // "BIN\0" little-endian

std::uint32_t read_u32_le(const std::uint8_t* bytes) {
    return std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 |
           std::uint32_t(bytes[2]) << 16 | std::uint32_t(bytes[3]) << 24;
}

std::string to_hex(std::uint32_t value) {
    static const char* digits = "0123456789ABCDEF";
    std::string text = "0x";
    for (int shift = 28; shift >= 0; shift -= 4) {
        text += digits[(value >> shift) & 0xF];
    }
    return text;
}

} // namespace

bool has_glb_magic(const std::uint8_t* bytes, std::size_t size_bytes) {
    return size_bytes >= 4 && std::memcmp(bytes, "glTF", 4) == 0;
}

frustum::Result<GlbJson> check_glb(const std::uint8_t* bytes, std::size_t size_bytes) {
    using frustum::Error;
    if (size_bytes < kHeaderBytes) {
        return Error{"truncated GLB: the file has " + std::to_string(size_bytes) +
                     " bytes, the GLB header needs " + std::to_string(kHeaderBytes)};
    }
    if (!has_glb_magic(bytes, size_bytes)) {
        return Error{"not a GLB file: the magic is not \"glTF\""};
    }
    const std::uint32_t version = read_u32_le(bytes + 4);
    if (version != 2) {
        return Error{"GLB version " + std::to_string(version) + " is not supported, expected 2"};
    }
    const std::uint32_t total_bytes = read_u32_le(bytes + 8);
    if (total_bytes != size_bytes) {
        return Error{"GLB header length " + std::to_string(total_bytes) +
                     " does not match the file size of " + std::to_string(size_bytes) +
                     " bytes (truncated or padded file)"};
    }

    GlbJson json;
    std::size_t offset = kHeaderBytes;
    for (int chunk = 0; offset < size_bytes; ++chunk) {
        const std::string name = "GLB chunk " + std::to_string(chunk);
        if (size_bytes - offset < kChunkHeaderBytes) {
            return Error{name + " header at byte " + std::to_string(offset) + " needs " +
                         std::to_string(kChunkHeaderBytes) + " bytes but only " +
                         std::to_string(size_bytes - offset) + " remain"};
        }
        const std::uint32_t chunk_bytes = read_u32_le(bytes + offset);
        const std::uint32_t chunk_type = read_u32_le(bytes + offset + 4);
        const std::size_t payload_offset = offset + kChunkHeaderBytes;
        if (chunk_bytes > size_bytes - payload_offset) {
            return Error{name + " length " + std::to_string(chunk_bytes) + " at byte " +
                         std::to_string(payload_offset) + " is larger than the " +
                         std::to_string(size_bytes - payload_offset) +
                         " bytes left in the file"};
        }
        if (chunk_bytes % 4 != 0) {
            return Error{name + " length " + std::to_string(chunk_bytes) +
                         " is not a multiple of 4"};
        }
        if (chunk == 0) {
            if (chunk_type != kChunkJson) {
                return Error{"GLB chunk 0 has type " + to_hex(chunk_type) +
                             ", expected JSON (" + to_hex(kChunkJson) + ")"};
            }
            if (chunk_bytes == 0) {
                return Error{"GLB chunk 0 (JSON) is empty"};
            }
            json.offset = payload_offset;
            json.size_bytes = chunk_bytes;
        } else if (chunk_type == kChunkJson) {
            return Error{name + " is a second JSON chunk"};
        } else if (chunk_type == kChunkBin && chunk != 1) {
            return Error{name + " is a BIN chunk; only chunk 1 may be BIN"};
        }
        offset = payload_offset + chunk_bytes;
    }
    return json;
}

} // namespace scene::detail
