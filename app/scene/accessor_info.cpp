#include "accessor_info.hpp"

namespace scene::detail {

std::size_t component_size_bytes(int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0; // INT and DOUBLE are not glTF accessor types
    }
}

std::size_t components_per_element(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

std::size_t element_size_bytes(int component_type, int type) {
    const std::size_t component = component_size_bytes(component_type);
    std::size_t rows = 0;
    if (type == TINYGLTF_TYPE_MAT2) rows = 2;
    if (type == TINYGLTF_TYPE_MAT3) rows = 3;
    if (rows != 0 && component < 4) {
        const std::size_t column_bytes = (rows * component + 3) / 4 * 4;
        return column_bytes * rows;
    }
    return component * components_per_element(type);
}

std::string component_type_name(int component_type) {
    const char* name = "not a glTF accessor type";
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: name = "BYTE"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: name = "UNSIGNED_BYTE"; break;
    case TINYGLTF_COMPONENT_TYPE_SHORT: name = "SHORT"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: name = "UNSIGNED_SHORT"; break;
    case TINYGLTF_COMPONENT_TYPE_INT: name = "INT, not allowed in accessors"; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: name = "UNSIGNED_INT"; break;
    case TINYGLTF_COMPONENT_TYPE_FLOAT: name = "FLOAT"; break;
    default: break;
    }
    return std::to_string(component_type) + " (" + name + ")";
}

std::string type_name(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "type " + std::to_string(type);
    }
}

std::string accessor_label(const tinygltf::Model& model, int accessor) {
    const std::string label = "accessor " + std::to_string(accessor);
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        const auto& primitives = model.meshes[m].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const std::string where =
                " of mesh " + std::to_string(m) + " primitive " + std::to_string(p) + ")";
            if (primitives[p].indices == accessor) {
                return label + " (indices" + where;
            }
            for (const auto& [semantic, index] : primitives[p].attributes) {
                if (index == accessor) {
                    return label + " (" + semantic + where;
                }
            }
        }
    }
    return label;
}

} // namespace scene::detail
