// KHR_draco_mesh_compression: each compressed primitive is decoded by
// libdraco (Debian's libdraco-dev) into a new buffer: one tightly packed
// bufferView per attribute the extension maps (in the accessor's declared
// component type) and one of UNSIGNED_INT indices, which the primitive's
// accessors then point at.
#include "decompress.hpp"

#include "accessor_info.hpp"
#include "extensions.hpp"

#include <draco/compression/decode.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Status;

// The bytes draco's attribute gives for every point, in `component_type`.
template <class T>
bool append_values(const draco::PointAttribute& attribute, std::size_t points, std::size_t components,
                   std::vector<unsigned char>& out) {
    std::vector<T> element(components);
    for (std::size_t p = 0; p < points; ++p) {
        const draco::AttributeValueIndex index = attribute.mapped_index(draco::PointIndex(std::uint32_t(p)));
        if (!attribute.ConvertValue<T>(index, static_cast<std::int8_t>(components), element.data())) {
            return false;
        }
        const auto* bytes = reinterpret_cast<const unsigned char*>(element.data());
        out.insert(out.end(), bytes, bytes + components * sizeof(T));
    }
    return true;
}

bool append_attribute(const draco::PointAttribute& attribute, int component_type, std::size_t points,
                      std::size_t components, std::vector<unsigned char>& out) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return append_values<std::int8_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return append_values<std::uint8_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return append_values<std::int16_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return append_values<std::uint16_t>(attribute, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return append_values<std::uint32_t>(attribute, points, components, out);
    default: return append_values<float>(attribute, points, components, out);
    }
}

// Points the accessor at `bytes` appended to `buffer` as a new bufferView.
void point_at(tinygltf::Model& model, int accessor, int buffer, std::vector<unsigned char>& bytes) {
    std::vector<unsigned char>& data = model.buffers[std::size_t(buffer)].data;
    data.resize((data.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = buffer;
    view.byteOffset = data.size();
    view.byteLength = bytes.size();
    data.insert(data.end(), bytes.begin(), bytes.end());
    model.bufferViews.push_back(view);
    tinygltf::Accessor& a = model.accessors[std::size_t(accessor)];
    a.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    a.byteOffset = 0;
    a.sparse.isSparse = false;
}

class DracoDecoder {
public:
    DracoDecoder(tinygltf::Model& model, std::uint64_t max_bytes) : model_(model), left_(max_bytes) {}

    Status primitive(tinygltf::Primitive& primitive, const tinygltf::Value& ext, const std::string& where) {
        if (!ext.IsObject() || !ext.Has("attributes") || !ext.Get("attributes").IsObject()) {
            return Error{where + " must be an object with a bufferView and an attributes object"};
        }
        frustum::Result<std::uint64_t> view = extension_count(ext, "bufferView", where);
        if (!view) return view.take_error();
        if (*view >= model_.bufferViews.size()) {
            return Error{where + " uses bufferView " + std::to_string(*view) + " but the file has " +
                         std::to_string(model_.bufferViews.size()) + " bufferViews"};
        }
        if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
            return Error{where + " is on a primitive of mode " + std::to_string(primitive.mode) +
                         ", expected 4 (TRIANGLES)"};
        }
        // Every accessor the decoder fills, with what it will cost, before decoding.
        std::uint64_t bytes = 0;
        auto declared = [&](int accessor, const std::string& label) -> Status {
            if (accessor < 0 || std::size_t(accessor) >= model_.accessors.size()) {
                return Error{where + " " + label + " uses accessor " + std::to_string(accessor) +
                             " but the file has " + std::to_string(model_.accessors.size()) + " accessors"};
            }
            const tinygltf::Accessor& a = model_.accessors[std::size_t(accessor)];
            const std::size_t element = element_size_bytes(a.componentType, a.type);
            if (element == 0) {
                return Error{where + " " + label + " (accessor " + std::to_string(accessor) + ") has componentType " +
                             component_type_name(a.componentType) + " and type " + type_name(a.type)};
            }
            if (a.count > left_) { // also keeps the sum below from overflowing
                bytes = left_ + 1;
                return {};
            }
            bytes += std::uint64_t(a.count) * (label == "indices" ? 4 : element);
            return {};
        };
        if (primitive.indices < 0) {
            return Error{where + " is on a primitive without indices"};
        }
        if (Status s = declared(primitive.indices, "indices"); !s) return s;
        const tinygltf::Value& attributes = ext.Get("attributes");
        for (const std::string& semantic : attributes.Keys()) {
            auto used = primitive.attributes.find(semantic);
            if (used == primitive.attributes.end()) {
                return Error{where + " maps " + semantic + ", which the primitive does not have"};
            }
            if (Status s = declared(used->second, semantic); !s) return s;
        }
        if (bytes > left_) {
            return Error{where + " decodes to " + std::to_string(bytes) + " bytes by its accessors' counts, over the "
                         "memory budget left (" + std::to_string(left_) + " bytes; raise it with --max-memory-mb)"};
        }
        left_ -= bytes;

        const tinygltf::BufferView& packed = model_.bufferViews[*view]; // inside its buffer
        draco::DecoderBuffer input;
        input.Init(reinterpret_cast<const char*>(model_.buffers[std::size_t(packed.buffer)].data.data() +
                                                 packed.byteOffset),
                   packed.byteLength);
        draco::Decoder decoder;
        auto decoded = decoder.DecodeMeshFromBuffer(&input);
        if (!decoded.ok()) {
            return Error{where + ": the Draco data (bufferView " + std::to_string(*view) + ", " +
                         std::to_string(packed.byteLength) + " bytes) does not decode: " +
                         decoded.status().error_msg_string()};
        }
        const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
        const std::size_t points = mesh->num_points();
        const std::size_t corners = std::size_t(mesh->num_faces()) * 3;

        const int buffer = out_buffer();
        const tinygltf::Accessor& index_accessor = model_.accessors[std::size_t(primitive.indices)];
        if (corners != index_accessor.count) {
            return Error{where + " decodes to " + std::to_string(corners) + " indices but its indices accessor " +
                         std::to_string(primitive.indices) + " has count " + std::to_string(index_accessor.count)};
        }
        std::vector<unsigned char> indices(corners * 4);
        for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
            const draco::Mesh::Face& face = mesh->face(f);
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t value = face[k].value();
                std::memcpy(indices.data() + (std::size_t(f.value()) * 3 + std::size_t(k)) * 4, &value, 4);
            }
        }
        model_.accessors[std::size_t(primitive.indices)].componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        point_at(model_, primitive.indices, buffer, indices);

        for (const std::string& semantic : attributes.Keys()) {
            const int accessor = primitive.attributes.at(semantic);
            const tinygltf::Accessor& a = model_.accessors[std::size_t(accessor)];
            frustum::Result<std::uint64_t> id = extension_count(attributes, semantic.c_str(), where + " attributes");
            if (!id) return id.take_error();
            const draco::PointAttribute* attribute =
                *id <= 0xFFFFFFFFu ? mesh->GetAttributeByUniqueId(static_cast<std::uint32_t>(*id)) : nullptr;
            if (attribute == nullptr) {
                return Error{where + " maps " + semantic + " to Draco attribute " + std::to_string(*id) +
                             ", which the decoded data does not have"};
            }
            if (points != a.count) {
                return Error{where + " decodes to " + std::to_string(points) + " points but " + semantic +
                             " (accessor " + std::to_string(accessor) + ") has count " + std::to_string(a.count)};
            }
            const std::size_t components = components_per_element(a.type);
            if (components > 4 || int(components) > attribute->num_components()) {
                return Error{where + " " + semantic + " is " + type_name(a.type) + " but Draco attribute " +
                             std::to_string(*id) + " has " + std::to_string(attribute->num_components()) +
                             " components"};
            }
            std::vector<unsigned char> values;
            values.reserve(points * components * component_size_bytes(a.componentType));
            if (!append_attribute(*attribute, a.componentType, points, components, values)) {
                return Error{where + " " + semantic + ": Draco attribute " + std::to_string(*id) +
                             " does not convert to " + component_type_name(a.componentType)};
            }
            point_at(model_, accessor, buffer, values);
        }
        return {};
    }

private:
    // The buffer the decoded data goes to, added on first use.
    int out_buffer() {
        if (buffer_ < 0) {
            model_.buffers.emplace_back();
            buffer_ = static_cast<int>(model_.buffers.size() - 1);
        }
        return buffer_;
    }

    tinygltf::Model& model_;
    std::uint64_t left_;
    int buffer_ = -1;
};

} // namespace

Status decode_draco(tinygltf::Model& model, std::uint64_t max_bytes) {
    DracoDecoder decoder(model, max_bytes);
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            auto found = primitive.extensions.find(kDraco);
            if (found == primitive.extensions.end()) continue;
            const std::string where = "mesh " + std::to_string(m) + " primitive " + std::to_string(p) + " " + kDraco;
            if (Status status = decoder.primitive(primitive, found->second, where); !status) {
                return status;
            }
        }
    }
    return {};
}

} // namespace scene::detail
