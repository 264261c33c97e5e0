#include "node_graph.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>


namespace scene::detail {

glm::dmat4 local_transform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        return glm::make_mat4(node.matrix.data());
    }
    glm::dmat4 transform(1.0);
    if (node.translation.size() == 3) {
        transform[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (node.rotation.size() == 4) {
        // glm::dquat takes (w, x, y, z); glTF stores (x, y, z, w).
        const glm::dquat rotation = glm::normalize(
            glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
        transform = transform * glm::mat4_cast(rotation);
    }
    if (node.scale.size() == 3) {
        transform = transform * glm::dmat4(glm::dvec4(node.scale[0], 0, 0, 0),
                                           glm::dvec4(0, node.scale[1], 0, 0),
                                           glm::dvec4(0, 0, node.scale[2], 0),
                                           glm::dvec4(0, 0, 0, 1));
    }
    return transform;
}

std::vector<int> root_nodes(const tinygltf::Model& model) {
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes) {
        for (int child : node.children) {
            is_child[child] = true;
        }
    }
    std::vector<int> roots;
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        if (!is_child[n]) {
            roots.push_back(static_cast<int>(n));
        }
    }
    return roots;
}

std::vector<WorldNode> flatten(const tinygltf::Model& model, const std::vector<int>& roots) {
    std::vector<WorldNode> flat;
    std::vector<WorldNode> stack; // pushed in reverse so pops come in file order
    for (auto root = roots.rbegin(); root != roots.rend(); ++root) {
        stack.push_back({*root, local_transform(model.nodes[*root])});
    }
    while (!stack.empty()) {
        WorldNode current = stack.back();
        stack.pop_back();
        const auto& children = model.nodes[current.node].children;
        for (auto child = children.rbegin(); child != children.rend(); ++child) {
            stack.push_back({*child, current.world * local_transform(model.nodes[*child])});
        }
        flat.push_back(current);
    }
    return flat;
}

} // namespace scene::detail
