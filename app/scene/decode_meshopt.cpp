// EXT_meshopt_compression: each compressed bufferView is decoded by
// libmeshoptimizer (Debian's libmeshoptimizer-dev) from its extension's
// range of another buffer into the view's own bytes (usually a "fallback"
// buffer the file holds no bytes for: parse_model() gives it zeros).
#include "decompress.hpp"

#include "extensions.hpp"

#include <meshoptimizer.h>

#include <string>
#include <vector>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Status;

std::string text_member(const tinygltf::Value& object, const char* key, const char* fallback) {
    if (!object.Has(key)) return fallback;
    const tinygltf::Value& value = object.Get(key);
    return value.IsString() ? value.Get<std::string>() : std::string();
}

Status decode_view(tinygltf::Model& model, std::size_t v, const tinygltf::Value& ext) {
    const std::string where = "bufferView " + std::to_string(v) + " " + kMeshopt;
    if (!ext.IsObject()) {
        return Error{where + " is not an object"};
    }
    frustum::Result<std::uint64_t> buffer = extension_count(ext, "buffer", where);
    frustum::Result<std::uint64_t> offset = extension_count(ext, "byteOffset", where, 0);
    frustum::Result<std::uint64_t> length = extension_count(ext, "byteLength", where);
    frustum::Result<std::uint64_t> stride = extension_count(ext, "byteStride", where);
    frustum::Result<std::uint64_t> count = extension_count(ext, "count", where);
    for (const auto* member : {&buffer, &offset, &length, &stride, &count}) {
        if (!*member) return Error{member->error()};
    }
    if (*buffer >= model.buffers.size()) {
        return Error{where + " uses buffer " + std::to_string(*buffer) + " but the file has " +
                     std::to_string(model.buffers.size()) + " buffers"};
    }
    const std::vector<unsigned char>& source = model.buffers[*buffer].data;
    if (*offset > source.size() || *length > source.size() - *offset) {
        return Error{where + " reads bytes [" + std::to_string(*offset) + ", " + std::to_string(*offset + *length) +
                     ") of buffer " + std::to_string(*buffer) + " which has " + std::to_string(source.size()) +
                     " bytes"};
    }
    const std::string mode = text_member(ext, "mode", "");
    const std::string filter = text_member(ext, "filter", "NONE");
    const bool attributes = mode == "ATTRIBUTES";
    if (!attributes && mode != "TRIANGLES" && mode != "INDICES") {
        return Error{where + " has mode \"" + mode + "\", expected ATTRIBUTES, TRIANGLES or INDICES"};
    }
    const bool stride_ok = attributes ? *stride >= 4 && *stride <= 256 && *stride % 4 == 0
                                      : *stride == 2 || *stride == 4;
    if (!stride_ok) {
        return Error{where + " has byteStride " + std::to_string(*stride) + " for mode " + mode + ", expected " +
                     (attributes ? "a multiple of 4 in 4..256" : "2 or 4")};
    }
    if (mode == "TRIANGLES" && *count % 3 != 0) {
        return Error{where + " has count " + std::to_string(*count) + " for mode TRIANGLES, expected a multiple of 3"};
    }
    const bool filter_ok = filter == "NONE" ||
                           (attributes && ((filter == "OCTAHEDRAL" && (*stride == 4 || *stride == 8)) ||
                                           (filter == "QUATERNION" && *stride == 8) || filter == "EXPONENTIAL"));
    if (!filter_ok) {
        return Error{where + " has filter \"" + filter + "\" with mode " + mode + " and byteStride " +
                     std::to_string(*stride) + "; allowed: NONE, or for ATTRIBUTES OCTAHEDRAL (byteStride 4 or 8), "
                     "QUATERNION (8), EXPONENTIAL"};
    }
    tinygltf::BufferView& view = model.bufferViews[v]; // inside its buffer: validate_buffer_views()
    if (*count > view.byteLength || *count * *stride > view.byteLength) {
        return Error{where + " decodes " + std::to_string(*count) + " x " + std::to_string(*stride) +
                     " bytes but the bufferView has " + std::to_string(view.byteLength) + " bytes"};
    }
    // A copy of the compressed bytes: the file may point them into the very view they decode to.
    const std::vector<unsigned char> packed(source.begin() + std::ptrdiff_t(*offset),
                                            source.begin() + std::ptrdiff_t(*offset + *length));
    unsigned char* out = model.buffers[view.buffer].data.data() + view.byteOffset;
    const int result = attributes ? meshopt_decodeVertexBuffer(out, *count, *stride, packed.data(), packed.size())
                       : mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out, *count, *stride, packed.data(), packed.size())
                                             : meshopt_decodeIndexSequence(out, *count, *stride, packed.data(), packed.size());
    if (result != 0) {
        return Error{where + ": the " + mode + " data (" + std::to_string(*length) + " bytes) does not decode to " +
                     std::to_string(*count) + " elements of " + std::to_string(*stride) +
                     " bytes (libmeshoptimizer error " + std::to_string(result) + ")"};
    }
    if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out, *count, *stride);
    if (filter == "QUATERNION") meshopt_decodeFilterQuat(out, *count, *stride);
    if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(out, *count, *stride);
    return {};
}

} // namespace

Status decode_meshopt(tinygltf::Model& model) {
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        auto found = model.bufferViews[v].extensions.find(kMeshopt);
        if (found == model.bufferViews[v].extensions.end()) continue;
        if (Status status = decode_view(model, v, found->second); !status) {
            return status;
        }
    }
    return {};
}

} // namespace scene::detail
