#include "validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Status;

Status check_texture_ref(const tinygltf::Model& model, const std::string& label, const char* slot,
                         int texture, int tex_coord) {
    if (texture < -1 || texture >= static_cast<int>(model.textures.size())) {
        return Error{label + " " + slot + " uses texture " + std::to_string(texture) +
                     " but the file has " + std::to_string(model.textures.size()) + " textures"};
    }
    if (tex_coord < 0) {
        return Error{label + " " + slot + " has texCoord " + std::to_string(tex_coord) +
                     ", expected >= 0"};
    }
    return {};
}

Status validate_material(const tinygltf::Model& model, int index) {
    const tinygltf::Material& material = model.materials[index];
    const std::string label = "material " + std::to_string(index);
    const auto& pbr = material.pbrMetallicRoughness;
    for (double factor : pbr.baseColorFactor) {
        if (!std::isfinite(factor)) {
            return Error{label + " baseColorFactor has a non-finite element"};
        }
    }
    Status checks[] = {
        check_texture_ref(model, label, "baseColorTexture", pbr.baseColorTexture.index,
                          pbr.baseColorTexture.texCoord),
        check_texture_ref(model, label, "metallicRoughnessTexture",
                          pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord),
        check_texture_ref(model, label, "normalTexture", material.normalTexture.index,
                          material.normalTexture.texCoord),
        check_texture_ref(model, label, "occlusionTexture", material.occlusionTexture.index,
                          material.occlusionTexture.texCoord),
        check_texture_ref(model, label, "emissiveTexture", material.emissiveTexture.index,
                          material.emissiveTexture.texCoord),
    };
    for (Status& status : checks) {
        if (!status) {
            return status;
        }
    }
    return {};
}

} // namespace

namespace {

// "2.0" -> (2, 0); false unless it is <major>.<minor> in digits.
bool parse_version(const std::string& text, long& major, long& minor) {
    const std::size_t dot = text.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 >= text.size() || text.size() > 16) {
        return false;
    }
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (i != dot && !(text[i] >= '0' && text[i] <= '9')) {
            return false;
        }
    }
    major = std::stol(text.substr(0, dot));
    minor = std::stol(text.substr(dot + 1));
    return true;
}

} // namespace

Status validate_asset(const tinygltf::Model& model) {
    long major = 0, minor = 0;
    const std::string& version = model.asset.version;
    if (!parse_version(version, major, minor)) {
        return Error{"asset.version is \"" + version + "\", expected \"<major>.<minor>\" such as \"2.0\""};
    }
    if (major != 2) {
        return Error{"asset.version is \"" + version +
                     "\": glTF major version " + std::to_string(major) +
                     " is not supported, expected 2"};
    }
    if (!model.asset.minVersion.empty()) {
        long min_major = 0, min_minor = 0;
        if (!parse_version(model.asset.minVersion, min_major, min_minor) || min_major != 2 ||
            min_minor > 0) {
            return Error{"asset.minVersion is \"" + model.asset.minVersion +
                         "\", but only glTF 2.0 is supported"};
        }
    }
    return {};
}

Status validate_images_textures_materials(const tinygltf::Model& model) {
    for (std::size_t i = 0; i < model.images.size(); ++i) {
        const tinygltf::Image& image = model.images[i];
        if (image.image.empty() && image.width <= 0) {
            continue; // not decoded because no texture draws it (parse_model())
        }
        const std::uint64_t expected_bytes =
            std::uint64_t(std::max(image.width, 0)) * std::uint64_t(std::max(image.height, 0)) * 4;
        if (image.width <= 0 || image.height <= 0 || image.component != 4 || image.bits != 8 ||
            image.image.size() != expected_bytes) {
            return Error{"image " + std::to_string(i) + " holds " + std::to_string(image.image.size()) +
                         " bytes for " + std::to_string(image.width) + " x " +
                         std::to_string(image.height) + " pixels of " + std::to_string(image.component) +
                         " x " + std::to_string(image.bits) + " bits, expected RGBA8"};
        }
    }
    for (std::size_t t = 0; t < model.textures.size(); ++t) {
        const tinygltf::Texture& texture = model.textures[t];
        const std::string label = "texture " + std::to_string(t);
        if (texture.source < -1 || texture.source >= static_cast<int>(model.images.size())) {
            return Error{label + " uses image " + std::to_string(texture.source) +
                         " but the file has " + std::to_string(model.images.size()) + " images"};
        }
        if (texture.sampler < -1 || texture.sampler >= static_cast<int>(model.samplers.size())) {
            return Error{label + " uses sampler " + std::to_string(texture.sampler) +
                         " but the file has " + std::to_string(model.samplers.size()) + " samplers"};
        }
    }
    for (std::size_t m = 0; m < model.materials.size(); ++m) {
        if (Status status = validate_material(model, static_cast<int>(m)); !status) {
            return status;
        }
    }
    return {};
}

Status validate_model(const tinygltf::Model& model) {
    using Check = Status (*)(const tinygltf::Model&);
    const Check checks[] = {validate_asset, validate_buffer_views,
                            validate_accessors, validate_meshes, validate_images_textures_materials,
                            validate_nodes, validate_scenes, validate_cameras, validate_morphs,
                            validate_instancing};
    for (Check check : checks) {
        if (Status status = check(model); !status) {
            return status;
        }
    }
    return {};
}

} // namespace scene::detail
