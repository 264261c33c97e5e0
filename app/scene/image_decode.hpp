// Encoded image bytes (PNG or JPEG, the formats glTF 2.0 allows) -> RGBA8.
#pragma once

#include "scene/scene.hpp"

#include <frustum/result.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace scene::detail {

// Rows top to bottom as stored; 16-bit channels are reduced to 8 bits and
// missing channels filled (grey -> RGB, alpha = 255). Rejects images with
// more than `max_pixels` pixels, or whose RGBA8 bytes would exceed
// `max_rgba_bytes` (what is left of the memory budget), before allocating
// them; `budget_note` ends that message ("... of the budget of 1 GiB (raise
// it with --max-memory-mb)"). Other formats stb_image knows (PNM, BMP, ...)
// are refused: a PNM header alone could claim gigapixels.
frustum::Result<image::Image> decode_rgba8(const std::uint8_t* bytes, std::size_t size_bytes,
                                    std::uint64_t max_pixels,
                                    std::uint64_t max_rgba_bytes = UINT64_MAX,
                                    const std::string& budget_note = {});

} // namespace scene::detail
