#include "decompress.hpp"

#include "validate.hpp"

#include <string>

namespace scene::detail {

frustum::Result<std::uint64_t> extension_count(const tinygltf::Value& object, const char* key,
                                               const std::string& where, long long fallback) {
    if (!object.Has(key)) {
        if (fallback < 0) {
            return frustum::Error{where + " has no " + key};
        }
        return static_cast<std::uint64_t>(fallback);
    }
    const tinygltf::Value& value = object.Get(key);
    // tinygltf keeps whole numbers as int (32 bits) and larger ones as real.
    const double number = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
    if (!(number >= 0.0 && number <= 9.007199254740992e15 && number == static_cast<double>(static_cast<std::uint64_t>(number)))) {
        return frustum::Error{where + " " + key + " must be a whole number >= 0"};
    }
    return static_cast<std::uint64_t>(number);
}

frustum::Status decompress(tinygltf::Model& model, const Budget& budget) {
    if (frustum::Status views = validate_buffer_views(model); !views) {
        return views;
    }
    if (frustum::Status meshopt = decode_meshopt(model); !meshopt) {
        return meshopt;
    }
    return decode_draco(model, budget.max_decoded_bytes);
}

} // namespace scene::detail
