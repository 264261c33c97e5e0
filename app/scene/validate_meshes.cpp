#include "accessor_info.hpp"
#include "extensions.hpp"
#include "validate.hpp"

#include <algorithm>
#include <initializer_list>
#include <string>
#include <vector>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Status;

constexpr int FLOAT = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int BYTE = TINYGLTF_COMPONENT_TYPE_BYTE;
constexpr int SHORT = TINYGLTF_COMPONENT_TYPE_SHORT;
constexpr int UBYTE = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int USHORT = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int UINT = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

// One allowed (type, componentType, normalized) combination.
struct Format {
    int type;
    int component_type;
    bool normalized;
};

struct AttributeRule {
    const char* prefix; // semantic, or semantic stem before "_<n>" when indexed
    bool indexed;
    std::vector<Format> formats;
    const char* allowed; // the same list, for messages
    // KHR_mesh_quantization's further formats (when the file uses it).
    std::vector<Format> quantized = {};
    const char* allowed_quantized = nullptr;
};

// Every integer component type of `types`, normalized and not, as `type`.
std::vector<Format> integer_formats(int type, std::initializer_list<int> types, bool plain, bool normalized) {
    std::vector<Format> formats;
    for (int component_type : types) {
        if (plain) formats.push_back({type, component_type, false});
        if (normalized) formats.push_back({type, component_type, true});
    }
    return formats;
}

// glTF 2.0 spec, "Meshes > Overview" attribute table.
const std::vector<AttributeRule>& attribute_rules() {
    static const std::vector<AttributeRule> rules = {
        {"POSITION", false, {{TINYGLTF_TYPE_VEC3, FLOAT, false}}, "VEC3 FLOAT",
         integer_formats(TINYGLTF_TYPE_VEC3, {BYTE, UBYTE, SHORT, USHORT}, true, true),
         "VEC3 of FLOAT or (normalized or not) BYTE/UNSIGNED_BYTE/SHORT/UNSIGNED_SHORT"},
        {"NORMAL", false, {{TINYGLTF_TYPE_VEC3, FLOAT, false}}, "VEC3 FLOAT",
         integer_formats(TINYGLTF_TYPE_VEC3, {BYTE, SHORT}, false, true),
         "VEC3 of FLOAT or normalized BYTE/SHORT"},
        {"TANGENT", false, {{TINYGLTF_TYPE_VEC4, FLOAT, false}}, "VEC4 FLOAT",
         integer_formats(TINYGLTF_TYPE_VEC4, {BYTE, SHORT}, false, true),
         "VEC4 of FLOAT or normalized BYTE/SHORT"},
        {"TEXCOORD_", true,
         {{TINYGLTF_TYPE_VEC2, FLOAT, false},
          {TINYGLTF_TYPE_VEC2, UBYTE, true},
          {TINYGLTF_TYPE_VEC2, USHORT, true}},
         "VEC2 of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT",
         integer_formats(TINYGLTF_TYPE_VEC2, {BYTE, UBYTE, SHORT, USHORT}, true, true),
         "VEC2 of FLOAT or (normalized or not) BYTE/UNSIGNED_BYTE/SHORT/UNSIGNED_SHORT"},
        {"COLOR_", true,
         {{TINYGLTF_TYPE_VEC3, FLOAT, false},
          {TINYGLTF_TYPE_VEC3, UBYTE, true},
          {TINYGLTF_TYPE_VEC3, USHORT, true},
          {TINYGLTF_TYPE_VEC4, FLOAT, false},
          {TINYGLTF_TYPE_VEC4, UBYTE, true},
          {TINYGLTF_TYPE_VEC4, USHORT, true}},
         "VEC3/VEC4 of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT"},
        {"JOINTS_", true,
         {{TINYGLTF_TYPE_VEC4, UBYTE, false}, {TINYGLTF_TYPE_VEC4, USHORT, false}},
         "VEC4 of UNSIGNED_BYTE/UNSIGNED_SHORT"},
        {"WEIGHTS_", true,
         {{TINYGLTF_TYPE_VEC4, FLOAT, false},
          {TINYGLTF_TYPE_VEC4, UBYTE, true},
          {TINYGLTF_TYPE_VEC4, USHORT, true}},
         "VEC4 of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT"},
    };
    return rules;
}

const AttributeRule* rule_for(const std::string& semantic) {
    for (const AttributeRule& rule : attribute_rules()) {
        const std::string prefix = rule.prefix;
        if (rule.indexed ? semantic.compare(0, prefix.size(), prefix) == 0 && semantic.size() > prefix.size()
                         : semantic == prefix) {
            return &rule;
        }
    }
    return nullptr; // application-specific ("_FOO") or unknown: range checks only
}

std::string accessor_in_range(const tinygltf::Model& model, int accessor) {
    if (accessor >= 0 && static_cast<std::size_t>(accessor) < model.accessors.size()) {
        return {};
    }
    return "uses accessor " + std::to_string(accessor) + " but the file has " +
           std::to_string(model.accessors.size()) + " accessors";
}

bool uses_quantization(const tinygltf::Model& model) {
    return std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), kMeshQuantization) !=
           model.extensionsUsed.end();
}

Status validate_attribute(const tinygltf::Model& model, const std::string& where,
                          const std::string& semantic, int index, std::size_t vertex_count) {
    const std::string label = semantic + " of " + where;
    if (std::string problem = accessor_in_range(model, index); !problem.empty()) {
        return Error{label + " " + problem};
    }
    const tinygltf::Accessor& accessor = model.accessors[index];
    if (const AttributeRule* rule = rule_for(semantic)) {
        const bool quantized = rule->allowed_quantized != nullptr && uses_quantization(model);
        bool allowed = false;
        for (const std::vector<Format>* formats : {&rule->formats, quantized ? &rule->quantized : nullptr}) {
            for (std::size_t f = 0; formats != nullptr && f < formats->size(); ++f) {
                const Format& format = (*formats)[f];
                allowed = allowed || (format.type == accessor.type &&
                                      format.component_type == accessor.componentType &&
                                      format.normalized == accessor.normalized);
            }
        }
        if (!allowed) {
            return Error{label + " (accessor " + std::to_string(index) + ") is " +
                         type_name(accessor.type) + " with componentType " +
                         component_type_name(accessor.componentType) +
                         (accessor.normalized ? " normalized" : "") + "; allowed: " +
                         (quantized ? rule->allowed_quantized : rule->allowed)};
        }
    }
    if (accessor.count != vertex_count) {
        return Error{label + " (accessor " + std::to_string(index) + ") has " +
                     std::to_string(accessor.count) + " elements but POSITION has " +
                     std::to_string(vertex_count)};
    }
    return {};
}

Status validate_indices(const tinygltf::Model& model, const std::string& where, int index) {
    const std::string label = "indices of " + where;
    if (std::string problem = accessor_in_range(model, index); !problem.empty()) {
        return Error{label + " " + problem};
    }
    const tinygltf::Accessor& accessor = model.accessors[index];
    const bool unsigned_type = accessor.componentType == UBYTE ||
                               accessor.componentType == USHORT || accessor.componentType == UINT;
    if (accessor.type != TINYGLTF_TYPE_SCALAR || !unsigned_type || accessor.normalized) {
        return Error{label + " (accessor " + std::to_string(index) + ") is " +
                     type_name(accessor.type) + " with componentType " +
                     component_type_name(accessor.componentType) +
                     (accessor.normalized ? " normalized" : "") +
                     "; allowed: SCALAR of UNSIGNED_BYTE/UNSIGNED_SHORT/UNSIGNED_INT"};
    }
    return {};
}

Status validate_primitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                          const std::string& where) {
    if (primitive.mode < TINYGLTF_MODE_POINTS || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN) {
        return Error{where + " has mode " + std::to_string(primitive.mode) +
                     ", expected 0..6 (POINTS..TRIANGLE_FAN)"};
    }
    if (primitive.material < -1 || primitive.material >= static_cast<int>(model.materials.size())) {
        return Error{where + " uses material " + std::to_string(primitive.material) +
                     " but the file has " + std::to_string(model.materials.size()) + " materials"};
    }
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
        // glTF 2.0 §3.7.2.1: "When positions are not specified, client
        // implementations SHOULD skip primitive's rendering"; build_mesh() does.
        return {};
    }
    if (std::string problem = accessor_in_range(model, position->second); !problem.empty()) {
        return Error{"POSITION of " + where + " " + problem};
    }
    const std::size_t vertex_count = model.accessors[position->second].count;
    for (const auto& [semantic, index] : primitive.attributes) {
        if (Status status = validate_attribute(model, where, semantic, index, vertex_count); !status) {
            return status;
        }
    }
    if (primitive.indices != -1) {
        if (Status status = validate_indices(model, where, primitive.indices); !status) {
            return status;
        }
    }
    for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
        for (const auto& [semantic, index] : primitive.targets[t]) {
            if (std::string problem = accessor_in_range(model, index); !problem.empty()) {
                return Error{"morph target " + std::to_string(t) + " " + semantic + " of " + where +
                             " " + problem};
            }
        }
    }
    return {};
}

} // namespace

Status validate_meshes(const tinygltf::Model& model) {
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        const auto& primitives = model.meshes[m].primitives;
        if (primitives.empty()) {
            return Error{"mesh " + std::to_string(m) + " has no primitives"};
        }
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const std::string where = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            if (Status status = validate_primitive(model, primitives[p], where); !status) {
                return status;
            }
        }
    }
    return {};
}

} // namespace scene::detail
