// Encoded image bytes (PNG, JPEG, or anything else stb_image reads) -> RGBA8.
#pragma once

#include "scene/scene.hpp"

#include <frustum/result.hpp>

#include <cstddef>
#include <cstdint>

namespace scene::detail {

// Rows top to bottom as stored; 16-bit channels are reduced to 8 bits and
// missing channels filled (grey -> RGB, alpha = 255). Rejects images with
// more than `max_pixels` pixels before allocating them.
frustum::Result<Image> decode_rgba8(const std::uint8_t* bytes, std::size_t size_bytes,
                                    std::uint64_t max_pixels);

} // namespace scene::detail
