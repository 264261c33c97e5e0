#include "validate.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace scene::detail {

namespace {

using frustum::Error;
using frustum::Status;

std::string num(double value) {
    std::string text = std::to_string(value);
    // std::to_string prints 6 decimals; trim trailing zeros for messages.
    if (text.find('.') != std::string::npos) {
        text.erase(text.find_last_not_of('0') + 1);
        if (text.back() == '.') text.pop_back();
    }
    return text;
}

std::string node_label(const tinygltf::Model& model, int node) {
    const std::string& name = model.nodes[node].name;
    return "node " + std::to_string(node) + (name.empty() ? "" : " (\"" + name + "\")");
}

Status check_index(const std::string& label, const char* what, const char* plural, int index,
                   std::size_t size) {
    if (index < -1 || index >= static_cast<int>(size)) {
        return Error{label + " uses " + what + " " + std::to_string(index) + " but the file has " +
                     std::to_string(size) + " " + plural};
    }
    return {};
}

Status check_vector(const std::string& label, const char* property,
                    const std::vector<double>& values, std::size_t expected) {
    if (!values.empty() && values.size() != expected) {
        return Error{label + " " + property + " has " + std::to_string(values.size()) +
                     " elements, expected " + std::to_string(expected)};
    }
    for (double value : values) {
        if (!std::isfinite(value)) {
            return Error{label + " " + property + " has a non-finite element"};
        }
    }
    return {};
}

Status validate_node(const tinygltf::Model& model, int index) {
    const tinygltf::Node& node = model.nodes[index];
    const std::string label = node_label(model, index);
    Status checks[] = {
        check_index(label, "mesh", "meshes", node.mesh, model.meshes.size()),
        check_index(label, "camera", "cameras", node.camera, model.cameras.size()),
        check_index(label, "skin", "skins", node.skin, model.skins.size()),
        check_vector(label, "matrix", node.matrix, 16),
        check_vector(label, "translation", node.translation, 3),
        check_vector(label, "rotation", node.rotation, 4),
        check_vector(label, "scale", node.scale, 3),
    };
    for (Status& status : checks) {
        if (!status) {
            return status;
        }
    }
    if (node.rotation.size() == 4) {
        const auto& q = node.rotation;
        const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (std::abs(length - 1.0) > 0.01) {
            return Error{label + " rotation quaternion has length " + num(length) +
                         ", expected 1"};
        }
    }
    for (int child : node.children) {
        if (child < 0 || static_cast<std::size_t>(child) >= model.nodes.size()) {
            return Error{label + " has child " + std::to_string(child) + " but the file has " +
                         std::to_string(model.nodes.size()) + " nodes"};
        }
    }
    return {};
}

// glTF nodes must form disjoint trees: one parent at most, no cycles.
Status validate_forest(const tinygltf::Model& model) {
    const int node_count = static_cast<int>(model.nodes.size());
    std::vector<int> parent(node_count, -1);
    for (int n = 0; n < node_count; ++n) {
        for (int child : model.nodes[n].children) {
            if (parent[child] != -1) {
                return Error{node_label(model, child) + " is a child of both node " +
                             std::to_string(parent[child]) + " and node " + std::to_string(n)};
            }
            parent[child] = n;
        }
    }
    // With one parent each, the nodes a walk down from the roots does not
    // reach are exactly those on or below a cycle: O(nodes) in all.
    std::vector<bool> reached(static_cast<std::size_t>(node_count), false);
    std::vector<int> stack;
    for (int n = 0; n < node_count; ++n) {
        if (parent[n] == -1) {
            stack.push_back(n);
        }
    }
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        reached[static_cast<std::size_t>(n)] = true;
        for (int child : model.nodes[n].children) {
            stack.push_back(child);
        }
    }
    for (int n = 0; n < node_count; ++n) {
        if (reached[static_cast<std::size_t>(n)]) {
            continue;
        }
        // Walk up until a node repeats: that node is on the cycle.
        std::vector<bool> seen(static_cast<std::size_t>(node_count), false);
        int on_cycle = n;
        while (!seen[static_cast<std::size_t>(on_cycle)]) {
            seen[static_cast<std::size_t>(on_cycle)] = true;
            on_cycle = parent[on_cycle];
        }
        // The message shows at most kShown links of the cycle.
        constexpr int kShown = 8;
        std::vector<int> cycle{on_cycle};
        for (int at = parent[on_cycle]; at != on_cycle; at = parent[at]) {
            cycle.push_back(at);
        }
        std::string path;
        const int length = static_cast<int>(cycle.size());
        for (int i = 0; i < std::min(length, kShown); ++i) {
            path += std::to_string(cycle[static_cast<std::size_t>(length - 1 - i)]) + " -> ";
        }
        path += length > kShown ? "..." : std::to_string(cycle.back());
        return Error{"the node graph has a cycle of " + std::to_string(length) +
                     (length == 1 ? " node" : " nodes") + " (parent -> child): " + path};
    }
    return {};
}

} // namespace

Status validate_nodes(const tinygltf::Model& model) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        if (Status status = validate_node(model, static_cast<int>(n)); !status) {
            return status;
        }
    }
    return validate_forest(model);
}

Status validate_scenes(const tinygltf::Model& model) {
    std::vector<int> parent(model.nodes.size(), -1);
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        for (int child : model.nodes[n].children) {
            parent[child] = static_cast<int>(n);
        }
    }
    for (std::size_t s = 0; s < model.scenes.size(); ++s) {
        const std::string label = "scene " + std::to_string(s);
        std::vector<bool> listed(model.nodes.size(), false);
        for (int node : model.scenes[s].nodes) {
            if (node < 0 || static_cast<std::size_t>(node) >= model.nodes.size()) {
                return Error{label + " lists node " + std::to_string(node) + " but the file has " +
                             std::to_string(model.nodes.size()) + " nodes"};
            }
            if (parent[node] != -1) {
                return Error{label + " lists " + node_label(model, node) +
                             " as a root, but it is a child of node " + std::to_string(parent[node])};
            }
            if (listed[node]) {
                return Error{label + " lists " + node_label(model, node) + " twice"};
            }
            listed[node] = true;
        }
    }
    if (model.defaultScene < -1 || model.defaultScene >= static_cast<int>(model.scenes.size())) {
        return Error{"the default scene is " + std::to_string(model.defaultScene) +
                     " but the file has " + std::to_string(model.scenes.size()) + " scenes"};
    }
    return {};
}

Status validate_cameras(const tinygltf::Model& model) {
    constexpr double kPi = 3.14159265358979323846;
    for (std::size_t c = 0; c < model.cameras.size(); ++c) {
        const tinygltf::Camera& camera = model.cameras[c];
        const std::string label = "camera " + std::to_string(c);
        if (camera.type == "perspective") {
            const auto& p = camera.perspective;
            if (!std::isfinite(p.yfov) || !(p.yfov > 0.0 && p.yfov < kPi)) {
                return Error{label + " yfov " + num(p.yfov) + " rad is not in (0, pi)"};
            }
            if (!std::isfinite(p.znear) || !(p.znear > 0.0)) {
                return Error{label + " znear " + num(p.znear) + " must be > 0"};
            }
            // tinygltf stores an absent zfar (infinite) and aspectRatio as 0.
            if (p.zfar != 0.0 && !(std::isfinite(p.zfar) && p.zfar > p.znear)) {
                return Error{label + " zfar " + num(p.zfar) + " must be > znear " + num(p.znear)};
            }
            if (p.aspectRatio != 0.0 && !(std::isfinite(p.aspectRatio) && p.aspectRatio > 0.0)) {
                return Error{label + " aspectRatio " + num(p.aspectRatio) + " must be > 0"};
            }
        } else if (camera.type == "orthographic") {
            const auto& o = camera.orthographic;
            if (!std::isfinite(o.xmag) || !std::isfinite(o.ymag) || o.xmag == 0.0 || o.ymag == 0.0) {
                return Error{label + " xmag " + num(o.xmag) + " and ymag " + num(o.ymag) +
                             " must be finite and non-zero"};
            }
            if (!std::isfinite(o.znear) || !(o.znear >= 0.0)) {
                return Error{label + " znear " + num(o.znear) + " must be >= 0"};
            }
            if (!std::isfinite(o.zfar) || !(o.zfar > o.znear)) {
                return Error{label + " zfar " + num(o.zfar) + " must be > znear " + num(o.znear)};
            }
        } else {
            return Error{label + " has type \"" + camera.type +
                         "\", expected \"perspective\" or \"orthographic\""};
        }
    }
    return {};
}

} // namespace scene::detail
