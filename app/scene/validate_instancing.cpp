#include "accessor_info.hpp"
#include "extensions.hpp"
#include "validate.hpp"

#include <string>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Status;

constexpr int FLOAT = TINYGLTF_COMPONENT_TYPE_FLOAT;

// EXT_mesh_gpu_instancing attributes and the formats its spec allows.
struct InstanceAttribute {
    const char* name;
    int type;
    bool normalized_allowed; // ROTATION: also normalized BYTE / SHORT
    const char* allowed;
};
constexpr InstanceAttribute kAttributes[] = {
    {"TRANSLATION", TINYGLTF_TYPE_VEC3, false, "VEC3 FLOAT"},
    {"ROTATION", TINYGLTF_TYPE_VEC4, true, "VEC4 FLOAT or normalized BYTE/SHORT"},
    {"SCALE", TINYGLTF_TYPE_VEC3, false, "VEC3 FLOAT"},
};

Status validate_node(const tinygltf::Model& model, int node_index, const tinygltf::Value& extension) {
    const std::string where = "node " + std::to_string(node_index) + " " + kGpuInstancing;
    if (model.nodes[node_index].mesh < 0) {
        return Error{where + " needs a mesh on the node"};
    }
    const tinygltf::Value& attributes = extension.Get("attributes");
    if (!extension.IsObject() || !attributes.IsObject()) {
        return Error{where + " has no \"attributes\" object"};
    }
    std::size_t count = 0;
    bool any = false;
    for (const InstanceAttribute& rule : kAttributes) {
        if (!attributes.Has(rule.name)) {
            continue;
        }
        const tinygltf::Value& value = attributes.Get(rule.name);
        const int index = value.IsInt() ? value.GetNumberAsInt() : -1;
        if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
            return Error{where + " " + rule.name + " uses accessor " + (value.IsInt() ? std::to_string(index) : "?") +
                         " but the file has " + std::to_string(model.accessors.size()) + " accessors"};
        }
        const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
        const bool normalized_ok = rule.normalized_allowed && accessor.normalized &&
                                   (accessor.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                    accessor.componentType == TINYGLTF_COMPONENT_TYPE_SHORT);
        const bool float_ok = accessor.componentType == FLOAT && !accessor.normalized;
        if (accessor.type != rule.type || !(float_ok || normalized_ok)) {
            return Error{where + " " + rule.name + " (accessor " + std::to_string(index) + ") is " +
                         type_name(accessor.type) + " with componentType " +
                         component_type_name(accessor.componentType) + (accessor.normalized ? " normalized" : "") +
                         "; allowed: " + rule.allowed};
        }
        if (any && accessor.count != count) {
            return Error{where + " " + rule.name + " (accessor " + std::to_string(index) + ") has " +
                         std::to_string(accessor.count) + " elements but the other attributes have " +
                         std::to_string(count)};
        }
        count = accessor.count;
        any = true;
    }
    if (!any || count == 0) {
        return Error{where + " has no instances (no TRANSLATION, ROTATION or SCALE with elements)"};
    }
    return {};
}

} // namespace

Status validate_instancing(const tinygltf::Model& model) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        auto found = model.nodes[n].extensions.find(kGpuInstancing);
        if (found == model.nodes[n].extensions.end()) {
            continue;
        }
        if (Status status = validate_node(model, static_cast<int>(n), found->second); !status) {
            return status;
        }
    }
    return {};
}

} // namespace scene::detail
