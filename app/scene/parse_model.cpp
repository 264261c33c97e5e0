#include "parse_model.hpp"

#include "foreign_message.hpp"
#include "budget_check.hpp"
#include "image_decode.hpp"

#include <exception>
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
};

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
        state->error = label + ": " + decoded.error();
        if (err) *err += state->error;
        return false;
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

} // namespace

frustum::Result<tinygltf::Model> parse_model(const std::vector<unsigned char>& file_bytes,
                                             bool is_glb, FsSandbox& sandbox,
                                             std::uint64_t max_image_pixels,
                                             const Budget& budget) {
    tinygltf::Model model;
    ImageLoaderState images{&model, max_image_pixels, budget.max_decoded_bytes, 0,
                            " of the budget of " + format_bytes(budget.max_decoded_bytes) +
                                " (raise it with --max-memory-mb)",
                            {}};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(sandbox.callbacks());
    loader.SetImageLoader(&load_image, &images);

    std::string error, warning;
    bool parsed = false;
    try {
        const auto size = static_cast<unsigned int>(file_bytes.size()); // < 4 GiB: checked by caller
        parsed = is_glb ? loader.LoadBinaryFromMemory(&model, &error, &warning, file_bytes.data(),
                                                      size, sandbox.root())
                        : loader.LoadASCIIFromString(
                              &model, &error, &warning,
                              reinterpret_cast<const char*>(file_bytes.data()), size, sandbox.root());
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
    // tinygltf only warns when an external image cannot be read.
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        if (model.images[i].image.empty()) {
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
