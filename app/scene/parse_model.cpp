#include "parse_model.hpp"

#include "foreign_message.hpp"
#include "budget_check.hpp"
#include "glb_check.hpp"
#include "extensions.hpp"
#include "image_decode.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <exception>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace scene::detail {

namespace {

struct ImageLoaderState {
    const tinygltf::Model* model = nullptr; // being filled by tinygltf
    std::uint64_t max_pixels = 0;
    std::uint64_t max_rgba_bytes = 0; // the memory budget
    std::uint64_t decoded_bytes = 0;  // RGBA8 bytes of the images decoded so far
    std::string budget_note;
    std::string error; // the first image error, already worded for the user
    // Images that could not be decoded (not PNG/JPEG, corrupt, over the
    // budget), worded for the user: an error only if a texture uses them.
    std::map<int, std::string> undecoded;
};

// The images some texture draws from (textures[t].source); an image only an
// extension names (EXT_texture_webp's source beside a PNG fallback) or no
// texture names is not drawn, so it need not decode.
std::set<int> texture_sources(const tinygltf::Model& model) {
    std::set<int> sources;
    for (const tinygltf::Texture& texture : model.textures) {
        sources.insert(texture.source);
    }
    return sources;
}

// tinygltf::LoadImageDataFunction. For an image in a bufferView tinygltf has
// checked the view and buffer indices but not the byte range, so `bytes` may
// point past the buffer: check before reading.
bool load_image(tinygltf::Image* image, const int image_index, std::string* err, std::string*,
                int, int, const unsigned char* bytes, int size_bytes, void* user_data) {
    auto* state = static_cast<ImageLoaderState*>(user_data);
    const std::string label = "image " + std::to_string(image_index);
    std::size_t length = static_cast<std::size_t>(size_bytes < 0 ? 0 : size_bytes);
    if (image->bufferView >= 0) {
        const tinygltf::BufferView& view = state->model->bufferViews[image->bufferView];
        const std::size_t buffer_bytes = state->model->buffers[view.buffer].data.size();
        if (view.byteOffset > buffer_bytes || view.byteLength > buffer_bytes - view.byteOffset) {
            state->error = label + " uses bufferView " + std::to_string(image->bufferView) +
                           " which covers bytes [" + std::to_string(view.byteOffset) + ", " +
                           std::to_string(std::uint64_t(view.byteOffset) + view.byteLength) +
                           ") of buffer " + std::to_string(view.buffer) + " which has " +
                           std::to_string(buffer_bytes) + " bytes";
            if (err) *err += state->error;
            return false;
        }
        length = view.byteLength;
    }
    const std::uint64_t left = state->max_rgba_bytes > state->decoded_bytes
                                   ? state->max_rgba_bytes - state->decoded_bytes : 0;
    frustum::Result<image::Image> decoded =
        decode_rgba8(bytes, length, state->max_pixels, left, state->budget_note);
    if (!decoded) {
        state->undecoded[image_index] = label + ": " + decoded.error();
        return true; // left empty; parse_model() decides once the textures are read
    }
    image->width = decoded->width;
    image->height = decoded->height;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(decoded->rgba);
    state->decoded_bytes += image->image.size();
    return true;
}

// An EXT_meshopt_compression "fallback" buffer: no bytes in the file (no uri,
// and not the GLB's BIN chunk), only what the compressed bufferViews decode to.
struct FallbackBuffer {
    std::size_t index = 0;
    std::uint64_t byte_length = 0;
};

bool is_meshopt_fallback(const nlohmann::json& buffer) {
    if (!buffer.is_object() || buffer.contains("uri")) return false;
    const auto extensions = buffer.find("extensions");
    if (extensions == buffer.end() || !extensions->is_object()) return false;
    const auto meshopt = extensions->find(kMeshopt);
    return meshopt != extensions->end() && meshopt->is_object() && meshopt->value("fallback", false) == true;
}

// tinygltf 2.7 requires the indices accessor of every primitive to have a
// bufferView; a Draco primitive's has none (its indices are in the
// compressed data). It is given the extension's bufferView, which
// decode_draco() replaces with the decoded indices.
void point_draco_indices_at_their_data(nlohmann::json& root) {
    auto meshes = root.find("meshes");
    auto accessors = root.find("accessors");
    if (meshes == root.end() || !meshes->is_array() || accessors == root.end() || !accessors->is_array()) return;
    for (nlohmann::json& mesh : *meshes) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
        for (nlohmann::json& primitive : mesh["primitives"]) {
            if (!primitive.is_object()) continue;
            const nlohmann::json* draco = nullptr;
            if (auto ext = primitive.find("extensions"); ext != primitive.end() && ext->is_object()) {
                if (auto found = ext->find(kDraco); found != ext->end() && found->is_object()) draco = &*found;
            }
            const auto indices = primitive.find("indices");
            if (draco == nullptr || indices == primitive.end() || !indices->is_number_unsigned() ||
                !draco->contains("bufferView") || !(*draco)["bufferView"].is_number_unsigned()) {
                continue;
            }
            const std::uint64_t index = indices->get<std::uint64_t>();
            if (index < accessors->size() && (*accessors)[index].is_object() &&
                !(*accessors)[index].contains("bufferView")) {
                (*accessors)[index]["bufferView"] = (*draco)["bufferView"];
            }
        }
    }
}

// The JSON as tinygltf 2.7 accepts it: without skins and animations (when
// asked), and each meshopt fallback buffer given a 3-byte data uri in place
// of the bytes it does not have (tinygltf requires a uri, or would copy the
// BIN chunk); `fallbacks` gets their declared byteLength; Draco indices
// accessors given a bufferView.
std::string json_for_tinygltf(const char* text, std::size_t size_bytes, bool strip_skins_and_animations,
                              bool is_glb, std::vector<FallbackBuffer>& fallbacks) {
    const nlohmann::json::parser_callback_t drop =
        [strip_skins_and_animations](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
            return !(strip_skins_and_animations && depth == 1 && event == nlohmann::json::parse_event_t::key &&
                     (parsed == "skins" || parsed == "animations"));
        };
    nlohmann::json root = nlohmann::json::parse(text, text + size_bytes, drop); // valid: checked before
    auto buffers = root.find("buffers");
    if (buffers != root.end() && buffers->is_array()) {
        for (std::size_t i = is_glb ? 1 : 0; i < buffers->size(); ++i) {
            nlohmann::json& buffer = (*buffers)[i];
            const auto length = buffer.find("byteLength");
            if (!is_meshopt_fallback(buffer) || length == buffer.end() || !length->is_number_unsigned()) continue;
            fallbacks.push_back({i, length->get<std::uint64_t>()});
            buffer["uri"] = "data:application/octet-stream;base64,AAAA";
            buffer["byteLength"] = 3;
        }
    }
    point_draco_indices_at_their_data(root);
    return root.dump();
}

bool mentions(const std::vector<unsigned char>& bytes, const std::string& word) {
    return std::search(bytes.begin(), bytes.end(), word.begin(), word.end()) != bytes.end();
}

// The file with its JSON replaced by `json` (for a GLB: the JSON chunk,
// padded with spaces to 4 bytes, the chunks after it unchanged).
std::vector<unsigned char> with_json(const std::vector<unsigned char>& file_bytes, bool is_glb,
                                     std::string json) {
    if (!is_glb) {
        return {json.begin(), json.end()};
    }
    const GlbJson old = *check_glb(file_bytes.data(), file_bytes.size()); // checked before
    json.resize((json.size() + 3) / 4 * 4, ' ');
    std::vector<unsigned char> bytes(file_bytes.begin(), file_bytes.begin() + 12);
    auto put_u32 = [&bytes](std::size_t at, std::uint32_t value) {
        for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<unsigned char>(value >> (8 * i));
    };
    bytes.resize(20);
    put_u32(12, static_cast<std::uint32_t>(json.size()));
    std::copy(file_bytes.begin() + 16, file_bytes.begin() + 20, bytes.begin() + 16); // "JSON"
    bytes.insert(bytes.end(), json.begin(), json.end());
    bytes.insert(bytes.end(), file_bytes.begin() + old.offset + old.size_bytes, file_bytes.end());
    put_u32(8, static_cast<std::uint32_t>(bytes.size()));
    return bytes;
}

} // namespace

frustum::Result<tinygltf::Model> parse_model(const std::vector<unsigned char>& file_bytes,
                                             bool is_glb, const JsonFacts& facts,
                                             FsSandbox& sandbox,
                                             std::uint64_t max_image_pixels,
                                             const Budget& budget) {
    tinygltf::Model model;
    ImageLoaderState images{&model, max_image_pixels, budget.max_decoded_bytes, 0,
                            " of the budget of " + format_bytes(budget.max_decoded_bytes) +
                                " (raise it with --max-memory-mb)",
                            {}, {}};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(sandbox.callbacks());
    loader.SetImageLoader(&load_image, &images);

    std::string error, warning;
    bool parsed = false;
    std::vector<FallbackBuffer> fallbacks;
    try {
        std::vector<unsigned char> stripped;
        if (facts.strip_skins_and_animations || mentions(file_bytes, kMeshopt) || mentions(file_bytes, kDraco)) {
            std::size_t json_offset = 0, json_bytes = file_bytes.size();
            if (is_glb) {
                const GlbJson json = *check_glb(file_bytes.data(), file_bytes.size());
                json_offset = json.offset;
                json_bytes = json.size_bytes;
            }
            stripped = with_json(file_bytes, is_glb,
                                 json_for_tinygltf(reinterpret_cast<const char*>(file_bytes.data()) + json_offset,
                                                   json_bytes, facts.strip_skins_and_animations, is_glb, fallbacks));
        }
        const std::vector<unsigned char>& input = stripped.empty() ? file_bytes : stripped;
        const auto size = static_cast<unsigned int>(input.size()); // < 4 GiB: checked by caller
        parsed = is_glb ? loader.LoadBinaryFromMemory(&model, &error, &warning, input.data(),
                                                      size, sandbox.root())
                        : loader.LoadASCIIFromString(
                              &model, &error, &warning,
                              reinterpret_cast<const char*>(input.data()), size, sandbox.root());
        if (facts.strip_skins_and_animations) {
            for (tinygltf::Node& node : model.nodes) {
                node.skin = -1; // its skin was removed with the others
            }
        }
    } catch (const std::exception& exception) {
        return frustum::Error{"tinygltf failed: " + foreign_message(exception.what())};
    }
    if (!images.error.empty()) {
        return frustum::Error{images.error};
    }
    if (!parsed || !error.empty()) {
        std::string message =
            "tinygltf: " + foreign_message(error.empty() ? "parse failed" : error);
        if (!sandbox.first_refusal().empty()) {
            message += " (" + sandbox.first_refusal() + ")";
        }
        return frustum::Error{message};
    }
    // The fallback buffers' zeros, which decompress() overwrites.
    std::uint64_t fallback_bytes = 0;
    for (const FallbackBuffer& fallback : fallbacks) {
        fallback_bytes += fallback.byte_length > budget.max_decoded_bytes ? budget.max_decoded_bytes + 1
                                                                          : fallback.byte_length;
        if (fallback_bytes > budget.max_decoded_bytes) {
            return frustum::Error{std::string(kMeshopt) + " fallback buffer " + std::to_string(fallback.index) +
                                  " has byteLength " + std::to_string(fallback.byte_length) +
                                  "; the fallback buffers' bytes " + over_memory_budget(budget)};
        }
        model.buffers[fallback.index].data.assign(fallback.byte_length, 0);
    }
    const std::set<int> drawn = texture_sources(model);
    for (const auto& [index, message] : images.undecoded) {
        if (drawn.count(index) != 0) {
            return frustum::Error{message};
        }
    }
    // tinygltf only warns when an external image cannot be read.
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        if (model.images[i].image.empty() && drawn.count(static_cast<int>(i)) != 0) {
            std::string message = "image " + std::to_string(i) + " (uri \"" + model.images[i].uri +
                                  "\") could not be read";
            if (!sandbox.first_refusal().empty()) {
                message += ": " + sandbox.first_refusal();
            }
            return frustum::Error{message};
        }
    }
    return model;
}

} // namespace scene::detail
