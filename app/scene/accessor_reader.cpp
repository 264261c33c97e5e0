#include "accessor_reader.hpp"

#include "accessor_info.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

namespace scene::detail {

namespace {

template <class T>
T load(const std::uint8_t* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return value;
}

// An integer component as float; normalized (glTF): divided by the type's
// maximum, signed ones clamped at -1.
template <class Int>
float integer_as_float(const std::uint8_t* bytes, bool normalized) {
    const float value = load<Int>(bytes);
    if (!normalized) {
        return value;
    }
    const float scaled = value / static_cast<float>(std::numeric_limits<Int>::max());
    return std::is_signed<Int>::value ? std::max(scaled, -1.0f) : scaled;
}

float component_as_float(const std::uint8_t* bytes, int component_type, bool normalized) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return integer_as_float<std::int8_t>(bytes, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return integer_as_float<std::uint8_t>(bytes, normalized);
    case TINYGLTF_COMPONENT_TYPE_SHORT: return integer_as_float<std::int16_t>(bytes, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return integer_as_float<std::uint16_t>(bytes, normalized);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return static_cast<float>(load<std::uint32_t>(bytes));
    default: return load<float>(bytes); // FLOAT: the only other validated type
    }
}

std::uint32_t component_as_uint(const std::uint8_t* bytes, int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<std::uint8_t>(bytes);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(bytes);
    default: return load<std::uint32_t>(bytes); // UNSIGNED_INT: validated
    }
}

const std::uint8_t* view_bytes(const tinygltf::Model& model, int view, std::size_t offset) {
    const tinygltf::BufferView& buffer_view = model.bufferViews[view];
    return model.buffers[buffer_view.buffer].data.data() + buffer_view.byteOffset + offset;
}

// Fills `out` (count * components values) with `convert(component bytes)`.
template <class T, class Convert>
frustum::Status read_accessor(const tinygltf::Model& model, int index, std::vector<T>& out,
                              Convert convert) {
    const tinygltf::Accessor& accessor = model.accessors[index];
    const std::size_t components = components_per_element(accessor.type);
    const std::size_t component_bytes = component_size_bytes(accessor.componentType);
    const std::size_t element_bytes = element_size_bytes(accessor.componentType, accessor.type);
    out.assign(accessor.count * components, T{});

    if (accessor.bufferView >= 0) {
        const std::size_t stride = model.bufferViews[accessor.bufferView].byteStride != 0
                                       ? model.bufferViews[accessor.bufferView].byteStride
                                       : element_bytes;
        const std::uint8_t* base = view_bytes(model, accessor.bufferView, accessor.byteOffset);
        for (std::size_t i = 0; i < accessor.count; ++i) {
            for (std::size_t c = 0; c < components; ++c) {
                out[i * components + c] = convert(base + i * stride + c * component_bytes);
            }
        }
    }

    if (!accessor.sparse.isSparse) {
        return {};
    }
    const auto& sparse = accessor.sparse;
    const std::uint8_t* indices =
        view_bytes(model, sparse.indices.bufferView, std::size_t(sparse.indices.byteOffset));
    const std::size_t index_bytes = component_size_bytes(sparse.indices.componentType);
    const std::uint8_t* values =
        view_bytes(model, sparse.values.bufferView, std::size_t(sparse.values.byteOffset));
    std::uint64_t previous = 0;
    for (int k = 0; k < sparse.count; ++k) {
        const std::uint32_t target = component_as_uint(indices + k * index_bytes,
                                                       sparse.indices.componentType);
        if (target >= accessor.count || (k > 0 && target <= previous)) {
            return frustum::Error{accessor_label(model, index) + " sparse index " + std::to_string(k) +
                                  " is " + std::to_string(target) +
                                  "; sparse indices must increase strictly and stay below count " +
                                  std::to_string(accessor.count)};
        }
        previous = target;
        for (std::size_t c = 0; c < components; ++c) {
            out[target * components + c] =
                convert(values + std::size_t(k) * element_bytes + c * component_bytes);
        }
    }
    return {};
}

} // namespace

frustum::Result<std::vector<float>> read_floats(const tinygltf::Model& model, int accessor) {
    std::vector<float> values;
    const int component_type = model.accessors[accessor].componentType;
    const bool normalized = model.accessors[accessor].normalized;
    frustum::Status status = read_accessor(model, accessor, values, [&](const std::uint8_t* bytes) {
        return component_as_float(bytes, component_type, normalized);
    });
    if (!status) {
        return status.take_error();
    }
    return values;
}

frustum::Result<std::vector<std::uint32_t>> read_uints(const tinygltf::Model& model, int accessor) {
    std::vector<std::uint32_t> values;
    const int component_type = model.accessors[accessor].componentType;
    frustum::Status status = read_accessor(model, accessor, values, [&](const std::uint8_t* bytes) {
        return component_as_uint(bytes, component_type);
    });
    if (!status) {
        return status.take_error();
    }
    return values;
}

} // namespace scene::detail
