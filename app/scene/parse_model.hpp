// tinygltf parse with the sandboxed file callbacks and our image decoder.
#pragma once

#include "fs_sandbox.hpp"
#include "uri_check.hpp"

#include "scene/load_gltf.hpp"

#include <frustum/result.hpp>

#include <tiny_gltf.h>

#include <cstdint>
#include <vector>

namespace scene::detail {

// `file_bytes` is the whole .gltf or .glb file, already through check_glb()
// (GLB), check_json_depth() and check_json_and_uris(). On success every
// image of the model is decoded to RGBA8 (component 4, bits 8). tinygltf's
// warnings are dropped; its errors (and exceptions) become the error.
// Images are decoded one at a time while their RGBA8 bytes stay within
// budget.max_decoded_bytes in total; the first that would exceed it is
// refused before it is decoded. With facts.strip_skins_and_animations the
// JSON's skins and animations are removed first (and nodes lose their
// skin), so tinygltf accepts what glTF 2.0 allows there.
frustum::Result<tinygltf::Model> parse_model(const std::vector<unsigned char>& file_bytes,
                                             bool is_glb, const JsonFacts& facts,
                                             FsSandbox& sandbox,
                                             std::uint64_t max_image_pixels,
                                             const Budget& budget = {});

} // namespace scene::detail
