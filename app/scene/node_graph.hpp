// The node forest of a validated model, flattened to world transforms.
#pragma once

#include <glm/glm.hpp>

#include <tiny_gltf.h>

#include <vector>

namespace scene::detail {

// T * R * S (rotation as the glTF quaternion x, y, z, w, renormalized), or
// the node's column-major `matrix` when it has one.
glm::dmat4 local_transform(const tinygltf::Node& node);

// Nodes that are nobody's child, in index order.
std::vector<int> root_nodes(const tinygltf::Model& model);

struct WorldNode {
    int node = -1;
    glm::dmat4 world{1.0};
};

// Depth-first pre-order walk of the trees below `roots` (children in file
// order), without recursion so deep hierarchies cannot exhaust the stack.
std::vector<WorldNode> flatten(const tinygltf::Model& model, const std::vector<int>& roots);

} // namespace scene::detail
