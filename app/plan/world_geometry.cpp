#include "plan/world_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace plan {
namespace {

// The cofactor of the model's 3x3: normals through a non-uniform scale.
glm::mat3 normal_matrix(const glm::mat4& model) {
    const glm::mat3 a(model);
    const glm::mat3 cofactor(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1]));
    return glm::determinant(a) < 0.0f ? -cofactor : cofactor;
}

// Triangle list indices of a list, strip or fan (glTF 2.0, "Meshes").
std::vector<std::uint32_t> triangle_list(const scene::Primitive& p) {
    const std::vector<std::uint32_t>& in = p.indices;
    std::vector<std::uint32_t> out;
    switch (p.mode) {
    case scene::PrimitiveMode::Triangles:
        out.assign(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(in.size() / 3 * 3));
        break;
    case scene::PrimitiveMode::TriangleStrip:
        for (std::size_t i = 2; i < in.size(); ++i) {
            const bool odd = (i % 2) == 1;
            out.insert(out.end(), {in[i - 2], odd ? in[i] : in[i - 1], odd ? in[i - 1] : in[i]});
        }
        break;
    case scene::PrimitiveMode::TriangleFan:
        for (std::size_t i = 2; i < in.size(); ++i) {
            out.insert(out.end(), {in[i - 1], in[i], in[0]});
        }
        break;
    default: break; // points and lines: not drawn by the non-affine effect
    }
    return out;
}

// The longest edge of the triangles `indices` draws, position(v) giving vertex v's.
template <class PositionOf>
float longest_edge_m(const std::vector<std::uint32_t>& indices, const PositionOf& position) {
    float longest = 0.0f;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) {
            const glm::vec3& a = position(indices[t + static_cast<std::size_t>(e)]);
            const glm::vec3& b = position(indices[t + static_cast<std::size_t>((e + 1) % 3)]);
            longest = std::max(longest, glm::length(a - b));
        }
    }
    return longest;
}

float longest_edge_m(const WorldPrimitive& p) {
    return longest_edge_m(p.indices, [&](std::uint32_t v) -> const glm::vec3& { return p.vertices[v].position; });
}

// A position placed by `model`, as placed_primitive() and placed_extent() place it.
glm::vec3 placed_position(const glm::mat4& model, const glm::vec3& position) {
    return glm::vec3(model * glm::vec4(position, 1.0f));
}

// Weights are whole multiples of 1/n and every product is summed in one
// expression, so the two triangles of a shared edge compute bit-identical
// points there (the third weight is exactly 0).
WorldVertex blend(const WorldVertex& a, const WorldVertex& b, const WorldVertex& c, int i, int j, int k, int n) {
    const float wa = static_cast<float>(i) / static_cast<float>(n);
    const float wb = static_cast<float>(j) / static_cast<float>(n);
    const float wc = static_cast<float>(k) / static_cast<float>(n);
    WorldVertex v;
    v.position = wa * a.position + wb * b.position + wc * c.position;
    v.normal = wa * a.normal + wb * b.normal + wc * c.normal;
    v.color = wa * a.color + wb * b.color + wc * c.color;
    v.texcoord = wa * a.texcoord + wb * b.texcoord + wc * c.texcoord;
    return v;
}

} // namespace

WorldGeometry WorldGeometry::in_object_space(const scene::Scene& scene) {
    WorldGeometry out;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        for (const scene::Primitive& p : scene.meshes[static_cast<std::size_t>(scene.instances[i].mesh)].primitives) {
            std::vector<std::uint32_t> indices = triangle_list(p);
            if (indices.empty()) {
                continue;
            }
            WorldPrimitive w;
            w.instance = static_cast<int>(i);
            w.material = p.material;
            if (p.material >= 0) {
                const scene::Material& m = scene.materials[static_cast<std::size_t>(p.material)];
                w.base_color_factor = m.base_color_factor;
                w.double_sided = m.double_sided;
                w.textured = m.base_color_texture >= 0;
            }
            w.has_normals = !p.normals.empty();
            w.vertices.resize(p.positions.size());
            for (std::size_t v = 0; v < p.positions.size(); ++v) {
                WorldVertex& out_vertex = w.vertices[v];
                out_vertex.position = p.positions[v];
                if (w.has_normals) {
                    out_vertex.normal = p.normals[v];
                }
                if (!p.colors.empty()) {
                    out_vertex.color = p.colors[v];
                }
                if (!p.texcoords.empty()) {
                    out_vertex.texcoord = p.texcoords[v];
                }
            }
            w.indices = std::move(indices);
            out.primitives.push_back(std::move(w));
        }
    }
    return out;
}

WorldPrimitive WorldGeometry::placed_primitive(std::size_t i, const std::vector<scene::Instance>& instances) const {
    WorldPrimitive p = primitives[i];
    const glm::mat4& model = instances.at(static_cast<std::size_t>(p.instance)).world;
    const glm::mat3 normals = normal_matrix(model);
    for (WorldVertex& v : p.vertices) {
        v.position = placed_position(model, v.position);
        v.normal = normals * v.normal;
    }
    if (glm::determinant(glm::mat3(model)) < 0.0f) { // glTF: a mirroring node reverses the winding
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            std::swap(p.indices[t + 1], p.indices[t + 2]);
        }
    }
    return p;
}

PrimitiveExtent WorldGeometry::placed_extent(std::size_t i, const std::vector<scene::Instance>& instances,
                                             std::vector<glm::vec3>& positions) const {
    const WorldPrimitive& p = primitives[i];
    const glm::mat4& model = instances.at(static_cast<std::size_t>(p.instance)).world;
    positions.clear();
    for (const WorldVertex& v : p.vertices) {
        positions.push_back(placed_position(model, v.position));
    }
    // The winding does not change an edge's length.
    return {longest_edge_m(p.indices, [&](std::uint32_t v) -> const glm::vec3& { return positions[v]; }),
            p.indices.size() / 3, p.vertices.size()};
}

WorldGeometry WorldGeometry::placed(const std::vector<scene::Instance>& instances) const {
    WorldGeometry out;
    out.primitives.reserve(primitives.size());
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        out.primitives.push_back(placed_primitive(i, instances));
    }
    return out;
}

WorldGeometry WorldGeometry::from_scene(const scene::Scene& scene) {
    return in_object_space(scene).placed(scene.instances);
}

namespace {

int subdivision(float longest_m, float max_edge_m) {
    const float ratio = std::ceil(longest_m / max_edge_m);
    return static_cast<int>(std::clamp(ratio, 1.0f, static_cast<float>(kMaxSubdivision)));
}

std::size_t split_count(const std::vector<PrimitiveExtent>& extents, float max_edge_m, bool& any_split) {
    std::size_t total = 0;
    any_split = false;
    for (const PrimitiveExtent& e : extents) {
        const auto n = static_cast<std::size_t>(max_edge_m > 0.0f ? subdivision(e.longest_edge_m, max_edge_m) : 1);
        any_split = any_split || n > 1;
        total += e.triangles * n * n;
    }
    return total;
}

std::vector<PrimitiveExtent> extents_of(const WorldGeometry& geometry) {
    std::vector<PrimitiveExtent> extents;
    extents.reserve(geometry.primitives.size());
    for (const WorldPrimitive& p : geometry.primitives) {
        extents.push_back(extent_of(p));
    }
    return extents;
}

} // namespace

PrimitiveExtent extent_of(const WorldPrimitive& primitive) {
    return {longest_edge_m(primitive), primitive.indices.size() / 3, primitive.vertices.size()};
}

std::size_t split_triangle_count(const WorldGeometry& geometry, float max_edge_m) {
    bool any_split = false;
    return split_count(extents_of(geometry), max_edge_m, any_split);
}

std::size_t split_vertex_count(const std::vector<PrimitiveExtent>& extents, float max_edge_m) {
    std::size_t total = 0;
    for (const PrimitiveExtent& e : extents) {
        const auto n = static_cast<std::size_t>(max_edge_m > 0.0f ? subdivision(e.longest_edge_m, max_edge_m) : 1);
        total += n == 1 ? e.vertices : e.triangles * (n + 1) * (n + 2) / 2;
    }
    return total;
}

float edge_within_budget(const std::vector<PrimitiveExtent>& extents, float max_edge_m, std::size_t max_triangles) {
    if (!(max_edge_m > 0.0f)) {
        return max_edge_m;
    }
    float edge_m = max_edge_m;
    bool any_split = false;
    while (split_count(extents, edge_m, any_split) > max_triangles && any_split) {
        edge_m *= 2.0f;
    }
    return edge_m;
}

float edge_within_budget(const WorldGeometry& geometry, float max_edge_m, std::size_t max_triangles) {
    return edge_within_budget(extents_of(geometry), max_edge_m, max_triangles);
}

WorldPrimitive subdivide(WorldPrimitive p, float max_edge_m) {
    const int n = max_edge_m > 0.0f ? subdivision(longest_edge_m(p), max_edge_m) : 1;
    if (n == 1) {
        return p;
    }
    // p keeps its attributes and gets the split's vertices and indices.
    const std::vector<WorldVertex> vertices = std::move(p.vertices);
    const std::vector<std::uint32_t> indices = std::move(p.indices);
    p.vertices.clear(); // moved from: valid, and now empty
    p.indices.clear();
    const std::size_t triangles = indices.size() / 3;
    const auto side = static_cast<std::size_t>(n);
    p.vertices.reserve(triangles * (side + 1) * (side + 2) / 2);
    p.indices.reserve(triangles * side * side * 3);
    // Grid point (j, k) of a triangle: weights (n - j - k, j, k) / n.
    const auto grid_index = [n](int j, int k) { return static_cast<std::uint32_t>(j * (n + 1) - j * (j - 1) / 2 + k); };
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const WorldVertex& a = vertices[indices[t]];
        const WorldVertex& b = vertices[indices[t + 1]];
        const WorldVertex& c = vertices[indices[t + 2]];
        const auto base = static_cast<std::uint32_t>(p.vertices.size());
        for (int j = 0; j <= n; ++j) {
            for (int k = 0; k <= n - j; ++k) {
                p.vertices.push_back(blend(a, b, c, n - j - k, j, k, n));
            }
        }
        for (int j = 0; j < n; ++j) {
            for (int k = 0; k < n - j; ++k) {
                // Same orientation as (a, b, c): steps in j go towards b, in k towards c.
                p.indices.insert(p.indices.end(),
                                 {base + grid_index(j, k), base + grid_index(j + 1, k), base + grid_index(j, k + 1)});
                if (k + 1 < n - j) {
                    p.indices.insert(p.indices.end(), {base + grid_index(j + 1, k), base + grid_index(j + 1, k + 1),
                                                       base + grid_index(j, k + 1)});
                }
            }
        }
    }
    return p;
}

WorldGeometry subdivide(const WorldGeometry& geometry, float max_edge_m) {
    if (!(max_edge_m > 0.0f)) {
        return geometry;
    }
    WorldGeometry out;
    out.primitives.reserve(geometry.primitives.size());
    for (const WorldPrimitive& p : geometry.primitives) {
        out.primitives.push_back(subdivide(p, max_edge_m));
    }
    return out;
}

} // namespace plan
