#include "accessor_info.hpp"
#include "validate.hpp"

#include <cmath>
#include <string>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Status;

// POSITION and NORMAL displacements are applied on the CPU (build_scene);
// other target attributes (TANGENT, TEXCOORD_n, COLOR_n) are ignored.
Status validate_target(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                       const std::map<std::string, int>& target, const std::string& where) {
    const std::size_t vertex_count = model.accessors[primitive.attributes.at("POSITION")].count;
    for (const char* semantic : {"POSITION", "NORMAL"}) {
        auto found = target.find(semantic);
        if (found == target.end()) {
            continue;
        }
        const tinygltf::Accessor& accessor = model.accessors[found->second]; // index checked by validate_meshes
        if (accessor.type != TINYGLTF_TYPE_VEC3 || accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
            return Error{where + " " + semantic + " (accessor " + std::to_string(found->second) + ") is " +
                         type_name(accessor.type) + " with componentType " +
                         component_type_name(accessor.componentType) + "; allowed: VEC3 FLOAT"};
        }
        if (accessor.count != vertex_count) {
            return Error{where + " " + semantic + " (accessor " + std::to_string(found->second) + ") has " +
                         std::to_string(accessor.count) + " elements but POSITION has " +
                         std::to_string(vertex_count)};
        }
    }
    return {};
}

Status check_weights(const std::vector<double>& weights, std::size_t targets, const std::string& owner) {
    if (!weights.empty() && weights.size() != targets) {
        return Error{owner + " has " + std::to_string(weights.size()) + " morph weights but its mesh has " +
                     std::to_string(targets) + " morph targets"};
    }
    for (std::size_t w = 0; w < weights.size(); ++w) {
        if (!std::isfinite(weights[w])) {
            return Error{owner + " morph weight " + std::to_string(w) + " is not finite"};
        }
    }
    return {};
}

} // namespace

Status validate_morphs(const tinygltf::Model& model) {
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        const tinygltf::Mesh& mesh = model.meshes[m];
        const std::size_t targets = mesh.primitives.front().targets.size(); // validate_meshes: not empty
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string where = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
            const auto& primitive = mesh.primitives[p];
            if (primitive.targets.size() != targets) {
                return Error{where + " has " + std::to_string(primitive.targets.size()) +
                             " morph targets but primitive 0 has " + std::to_string(targets) +
                             " (glTF: every primitive of a mesh has the same number)"};
            }
            for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
                const std::string label = "morph target " + std::to_string(t) + " of " + where;
                if (Status status = validate_target(model, primitive, primitive.targets[t], label); !status) {
                    return status;
                }
            }
        }
        if (Status status = check_weights(mesh.weights, targets, "mesh " + std::to_string(m)); !status) {
            return status;
        }
    }
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const tinygltf::Node& node = model.nodes[n];
        if (node.weights.empty()) {
            continue;
        }
        if (node.mesh < 0) {
            return Error{"node " + std::to_string(n) + " has morph weights but no mesh"};
        }
        const std::size_t targets = model.meshes[node.mesh].primitives.front().targets.size();
        if (Status status = check_weights(node.weights, targets, "node " + std::to_string(n)); !status) {
            return status;
        }
    }
    return {};
}

} // namespace scene::detail
