#include "budget_check.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Status;

constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();

std::uint64_t add(std::uint64_t a, std::uint64_t b) { return a > kMax - b ? kMax : a + b; }
std::uint64_t mul(std::uint64_t a, std::uint64_t b) { return b != 0 && a > kMax / b ? kMax : a * b; }

std::uint64_t accessor_count(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                             const char* semantic) {
    auto found = primitive.attributes.find(semantic);
    return found == primitive.attributes.end() ? 0 : model.accessors[found->second].count;
}

struct PrimitiveCost {
    std::uint64_t decoded_bytes = 0; // as scene::Primitive holds it
    std::uint64_t drawn_vertices = 0;
};

// What build_primitive() will allocate: the attributes it reads and 4 bytes
// per index (an unindexed primitive gets 0, 1, 2, ... of its vertex count).
PrimitiveCost cost_of(const tinygltf::Model& model, const tinygltf::Primitive& primitive) {
    const std::uint64_t vertices = accessor_count(model, primitive, "POSITION");
    const std::uint64_t indices =
        primitive.indices >= 0 ? model.accessors[primitive.indices].count : vertices;
    std::uint64_t bytes = mul(vertices, 12);
    bytes = add(bytes, mul(accessor_count(model, primitive, "NORMAL"), 12));
    bytes = add(bytes, mul(accessor_count(model, primitive, "TEXCOORD_0"), 8));
    bytes = add(bytes, mul(accessor_count(model, primitive, "COLOR_0"), 16));
    bytes = add(bytes, mul(indices, 4));
    return {bytes, indices};
}

Status over(const std::string& what, std::uint64_t value, std::uint64_t limit, const char* option) {
    return Error{what + " is " + std::to_string(value) + ", over the limit of " +
                 std::to_string(limit) + " (raise it with " + option + ")"};
}

} // namespace

std::string format_bytes(std::uint64_t bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    double value = static_cast<double>(bytes);
    int unit = 0;
    while (value >= 1024.0 && unit < 6) {
        value /= 1024.0;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text, value == static_cast<double>(static_cast<std::uint64_t>(value))
                                         ? "%.0f %s" : "%.1f %s", value, units[unit]);
    return text;
}

std::string over_memory_budget(const Budget& budget) {
    return "is over the budget of " + format_bytes(budget.max_decoded_bytes) +
           " (raise it with --max-memory-mb)";
}

Status check_budget(const tinygltf::Model& model, const Budget& budget,
                    std::uint64_t decoded_image_bytes) {
    if (model.nodes.size() > budget.max_nodes) {
        return over("the node count", model.nodes.size(), budget.max_nodes, "--max-nodes");
    }
    std::uint64_t primitive_count = 0;
    for (const tinygltf::Mesh& mesh : model.meshes) {
        primitive_count += mesh.primitives.size();
    }
    if (primitive_count > budget.max_nodes) {
        return over("the mesh primitive count", primitive_count, budget.max_nodes, "--max-nodes");
    }

    // Each mesh is decoded once however many nodes draw it.
    std::vector<PrimitiveCost> mesh_costs(model.meshes.size());
    std::uint64_t decoded = decoded_image_bytes;
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        for (const tinygltf::Primitive& primitive : model.meshes[m].primitives) {
            const PrimitiveCost cost = cost_of(model, primitive);
            mesh_costs[m].decoded_bytes = add(mesh_costs[m].decoded_bytes, cost.decoded_bytes);
            mesh_costs[m].drawn_vertices = add(mesh_costs[m].drawn_vertices, cost.drawn_vertices);
        }
        decoded = add(decoded, mesh_costs[m].decoded_bytes);
    }
    if (decoded > budget.max_decoded_bytes) {
        return Error{"the scene decodes to " + format_bytes(decoded) + " (" +
                     format_bytes(decoded - decoded_image_bytes) + " of vertices and indices, " +
                     format_bytes(decoded_image_bytes) + " of images), which " +
                     over_memory_budget(budget)};
    }

    // One iterative walk over every tree of the forest (validate_nodes()
    // has ruled out cycles and second parents): depth and drawn vertices.
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes) {
        for (int child : node.children) {
            is_child[static_cast<std::size_t>(child)] = true;
        }
    }
    std::vector<std::pair<int, std::uint64_t>> stack; // node, its depth
    std::uint64_t drawn = 0;
    for (std::size_t root = 0; root < model.nodes.size(); ++root) {
        if (is_child[root]) {
            continue;
        }
        stack.push_back({static_cast<int>(root), 1});
        while (!stack.empty()) {
            const auto [index, depth] = stack.back();
            stack.pop_back();
            if (depth > budget.max_depth) {
                return over("the node hierarchy depth (at node " + std::to_string(index) + ")",
                            depth, budget.max_depth, "--max-depth");
            }
            const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
            if (node.mesh >= 0) {
                drawn = add(drawn, mesh_costs[static_cast<std::size_t>(node.mesh)].drawn_vertices);
                if (drawn > budget.max_drawn_vertices) {
                    return over("the vertex count drawn per frame (reached at node " +
                                    std::to_string(index) + ")",
                                drawn, budget.max_drawn_vertices, "--max-drawn-vertices");
                }
            }
            for (int child : node.children) {
                stack.push_back({child, depth + 1});
            }
        }
    }
    return {};
}

} // namespace scene::detail
