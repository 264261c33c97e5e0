#include "accessor_info.hpp"
#include "validate.hpp"

#include <string>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Status;

constexpr std::size_t kMaxZeroFilledCount = std::size_t(1) << 24;

std::string byte_range(std::uint64_t begin, std::uint64_t end) {
    return "[" + std::to_string(begin) + ", " + std::to_string(end) + ")";
}

std::string count_of(std::size_t count, const char* what) {
    return std::to_string(count) + " " + what;
}

// Empty when `size_bytes` bytes at `offset` of bufferView `view` lie inside
// it, else what is wrong (to follow the reader's name).
std::string view_range_problem(const tinygltf::Model& model, int view, std::uint64_t offset,
                               std::uint64_t size_bytes) {
    if (view < 0 || static_cast<std::size_t>(view) >= model.bufferViews.size()) {
        return "uses bufferView " + std::to_string(view) + " but the file has " +
               count_of(model.bufferViews.size(), "bufferViews");
    }
    const std::uint64_t view_bytes = model.bufferViews[view].byteLength;
    if (offset > view_bytes || size_bytes > view_bytes - offset) {
        return "reads bytes " + byte_range(offset, offset + size_bytes) + " of bufferView " +
               std::to_string(view) + " which has " + std::to_string(view_bytes) + " bytes";
    }
    return {};
}

// Checks the sparse part; returns what is wrong, to follow the accessor's name.
std::string sparse_problem(const tinygltf::Model& model, const tinygltf::Accessor& accessor) {
    const auto& sparse = accessor.sparse;
    if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > accessor.count) {
        return "has sparse.count " + std::to_string(sparse.count) + ", expected 1.." +
               std::to_string(accessor.count);
    }
    const int index_type = sparse.indices.componentType;
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        return "has sparse indices of componentType " + component_type_name(index_type) +
               "; allowed: UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT";
    }
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
        return "has a negative sparse byteOffset";
    }
    const std::uint64_t count = static_cast<std::uint64_t>(sparse.count);
    if (std::string problem = view_range_problem(model, sparse.indices.bufferView,
                                                 std::uint64_t(sparse.indices.byteOffset),
                                                 count * component_size_bytes(index_type));
        !problem.empty()) {
        return "sparse indices " + problem;
    }
    if (std::string problem = view_range_problem(
            model, sparse.values.bufferView, std::uint64_t(sparse.values.byteOffset),
            count * element_size_bytes(accessor.componentType, accessor.type));
        !problem.empty()) {
        return "sparse values " + problem;
    }
    return {};
}

Status validate_accessor(const tinygltf::Model& model, int index) {
    const tinygltf::Accessor& accessor = model.accessors[index];
    // Naming the accessor's use scans the meshes: only done for a message.
    auto label = [&] { return accessor_label(model, index); };
    const std::size_t component_bytes = component_size_bytes(accessor.componentType);
    if (component_bytes == 0) {
        return Error{label() + " has componentType " + component_type_name(accessor.componentType) +
                     "; allowed: 5120..5123, 5125, 5126"};
    }
    if (accessor.count < 1) {
        return Error{label() + " has count 0, expected >= 1"};
    }
    if (accessor.normalized && (accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
        return Error{label() + " is normalized but has componentType " +
                     component_type_name(accessor.componentType)};
    }
    if (accessor.sparse.isSparse) {
        if (std::string problem = sparse_problem(model, accessor); !problem.empty()) {
            return Error{label() + " " + problem};
        }
    }
    if (accessor.bufferView < 0) {
        // No data: zeros (plus sparse values). Bound what the reader allocates.
        if (accessor.count > kMaxZeroFilledCount) {
            return Error{label() + " has no bufferView and count " + std::to_string(accessor.count) +
                         "; at most " + std::to_string(kMaxZeroFilledCount) +
                         " zero-filled elements are accepted"};
        }
        return {};
    }
    if (std::string problem = view_range_problem(model, accessor.bufferView, 0, 0); !problem.empty()) {
        return Error{label() + " " + problem}; // the bufferView index is out of range
    }
    const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
    const std::size_t element_bytes = element_size_bytes(accessor.componentType, accessor.type);
    if (view.byteStride != 0 && view.byteStride < element_bytes) {
        return Error{label() + " has " + std::to_string(element_bytes) + "-byte elements (" +
                     type_name(accessor.type) + " of " +
                     component_type_name(accessor.componentType) + ") but bufferView " +
                     std::to_string(accessor.bufferView) + " has byteStride " +
                     std::to_string(view.byteStride)};
    }
    if (accessor.byteOffset % component_bytes != 0 ||
        (view.byteOffset + accessor.byteOffset) % component_bytes != 0) {
        return Error{label() + " starts at byte " + std::to_string(accessor.byteOffset) +
                     " of bufferView " + std::to_string(accessor.bufferView) + " (byte " +
                     std::to_string(view.byteOffset + accessor.byteOffset) +
                     " of its buffer), not a multiple of its " + std::to_string(component_bytes) +
                     "-byte component size"};
    }
    if (accessor.count > view.byteLength) { // also keeps the product below from overflowing
        return Error{label() + " has count " + std::to_string(accessor.count) +
                     ", more elements than bufferView " + std::to_string(accessor.bufferView) +
                     " has bytes (" + std::to_string(view.byteLength) + ")"};
    }
    const std::uint64_t stride = view.byteStride != 0 ? view.byteStride : element_bytes;
    const std::uint64_t read_bytes = stride * (accessor.count - 1) + element_bytes;
    if (std::string problem =
            view_range_problem(model, accessor.bufferView, accessor.byteOffset, read_bytes);
        !problem.empty()) {
        return Error{label() + " " + problem};
    }
    return {};
}

} // namespace

Status validate_buffer_views(const tinygltf::Model& model) {
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        const tinygltf::BufferView& view = model.bufferViews[v];
        const std::string label = "bufferView " + std::to_string(v);
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) {
            return Error{label + " uses buffer " + std::to_string(view.buffer) +
                         " but the file has " + count_of(model.buffers.size(), "buffers")};
        }
        if (view.byteLength < 1) {
            return Error{label + " has byteLength 0, expected >= 1"};
        }
        const std::uint64_t buffer_bytes = model.buffers[view.buffer].data.size();
        if (view.byteOffset > buffer_bytes || view.byteLength > buffer_bytes - view.byteOffset) {
            return Error{label + " covers bytes " +
                         byte_range(view.byteOffset, std::uint64_t(view.byteOffset) + view.byteLength) +
                         " of buffer " + std::to_string(view.buffer) + " which has " +
                         std::to_string(buffer_bytes) + " bytes"};
        }
        if (view.byteStride != 0 && view.byteStride < 4) {
            return Error{label + " has byteStride " + std::to_string(view.byteStride) +
                         ", expected 4..252"};
        }
    }
    return {};
}

Status validate_accessors(const tinygltf::Model& model) {
    for (std::size_t a = 0; a < model.accessors.size(); ++a) {
        if (Status status = validate_accessor(model, static_cast<int>(a)); !status) {
            return status;
        }
    }
    return {};
}

} // namespace scene::detail
