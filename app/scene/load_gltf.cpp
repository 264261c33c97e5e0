#include "scene/load_gltf.hpp"

#include "budget_check.hpp"
#include "build_scene.hpp"
#include "decompress.hpp"
#include "fs_sandbox.hpp"
#include "glb_check.hpp"
#include "json_depth.hpp"
#include "parse_model.hpp"
#include "uri_check.hpp"
#include "validate.hpp"

#include "text/one_line.hpp"

#include <cstdio>
#include <limits>
#include <utility>

namespace scene {

namespace {

using frustum::Error;
using frustum::Status;

// Where the JSON text starts in a .gltf: after a UTF-8 BOM and whitespace.
bool looks_like_json_object(const std::vector<unsigned char>& bytes) {
    std::size_t i = 0;
    if (bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF) {
        i = 3;
    }
    while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\n' ||
                                bytes[i] == '\r')) {
        ++i;
    }
    return i < bytes.size() && bytes[i] == '{';
}

std::string first_bytes_hex(const std::vector<unsigned char>& bytes) {
    std::string text;
    for (std::size_t i = 0; i < bytes.size() && i < 4; ++i) {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%02X", bytes[i]);
        text += (i ? " " : "") + std::string(hex);
    }
    return text;
}

// Container and JSON checks that must pass before tinygltf sees the bytes.
frustum::Result<detail::JsonFacts> preflight(const std::vector<unsigned char>& bytes, bool is_glb,
                                             const Budget& budget) {
    if (bytes.empty()) {
        return Error{"the file is empty"};
    }
    if (bytes.size() > std::numeric_limits<unsigned int>::max()) {
        return Error{"the file has " + std::to_string(bytes.size()) +
                     " bytes; tinygltf reads at most 4 GiB"};
    }
    std::size_t json_offset = 0;
    std::size_t json_bytes = bytes.size();
    if (is_glb) {
        frustum::Result<detail::GlbJson> json = detail::check_glb(bytes.data(), bytes.size());
        if (!json) {
            return json.take_error();
        }
        json_offset = json->offset;
        json_bytes = json->size_bytes;
    } else if (!looks_like_json_object(bytes)) {
        return Error{"not a glTF file: neither GLB (magic \"glTF\") nor a JSON object (first bytes " +
                     first_bytes_hex(bytes) + ")"};
    }
    const char* json = reinterpret_cast<const char*>(bytes.data()) + json_offset;
    if (Status depth = detail::check_json_depth(json, json_bytes); !depth) {
        return Error{depth.error()};
    }
    return detail::check_json_and_uris(json, json_bytes, budget);
}

} // namespace

frustum::Result<Scene> load_gltf(const std::string& path, const LoadOptions& options) {
    // Messages are one line: file names and uris from the input may hold
    // control characters, which are shown escaped.
    auto fail = [&path](const std::string& what) {
        return Error{"scene::load_gltf(): " + text::one_line(path) + ": " + text::one_line(what)};
    };
    frustum::Result<detail::FsSandbox> sandbox =
        detail::FsSandbox::for_model(path, options.max_file_bytes);
    if (!sandbox) {
        return fail(sandbox.error());
    }
    frustum::Result<std::vector<unsigned char>> bytes = sandbox->read(path);
    if (!bytes) {
        return fail(bytes.error());
    }
    const bool is_glb = detail::has_glb_magic(bytes->data(), bytes->size());
    frustum::Result<detail::JsonFacts> facts = preflight(*bytes, is_glb, options.budget);
    if (!facts) {
        return fail(facts.error());
    }
    frustum::Result<tinygltf::Model> model = detail::parse_model(
        *bytes, is_glb, *facts, *sandbox, options.max_image_pixels, options.budget);
    if (!model) {
        return fail(model.error());
    }
    if (Status decoded = detail::decompress(*model, options.budget); !decoded) {
        return fail(decoded.error());
    }
    if (Status valid = detail::validate_model(*model); !valid) {
        return fail(valid.error());
    }
    std::uint64_t image_bytes = 0;
    for (const tinygltf::Image& image : model->images) {
        image_bytes += image.image.size();
    }
    if (Status fits = detail::check_budget(*model, options.budget, image_bytes); !fits) {
        return fail(fits.error());
    }
    frustum::Result<Scene> scene = detail::build_scene(std::move(*model), options);
    if (!scene) {
        return fail(scene.error());
    }
    return scene;
}

} // namespace scene
