// The scene's triangles flattened to world space on the CPU, for the
// non-affine effect (eq. 36 is not a matrix, so the GPU cannot take a model
// matrix through it for free and the CPU must see every vertex to cull) and
// for its ray-cast reference. Points and lines are left out.
#pragma once

#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace plan {

struct WorldVertex {
    glm::vec3 position{0.0f}; // world, metres
    glm::vec3 normal{0.0f, 0.0f, 1.0f}; // world, not normalized (the shader normalizes)
    glm::vec4 color{1.0f};    // COLOR_0, linear; white when absent
    glm::vec2 texcoord{0.0f};
};

// One primitive of one instance: a triangle list, counter-clockwise from the
// front (the winding of a mirroring instance transform is undone here).
struct WorldPrimitive {
    std::vector<WorldVertex> vertices;
    std::vector<std::uint32_t> indices; // 3 per triangle
    int instance = -1;
    int material = -1; // into scene.materials (GpuScene::material()), -1 = default
    glm::vec4 base_color_factor{1.0f};
    bool double_sided = false;
    bool has_normals = false;
    bool textured = false;
};

// What the split's budget needs of one primitive: subdivide() splits it by
// its longest edge, into n x n triangles of (n + 1)(n + 2) / 2 vertices each.
struct PrimitiveExtent {
    float longest_edge_m = 0.0f;
    std::size_t triangles = 0;
    std::size_t vertices = 0;
};

struct WorldGeometry {
    std::vector<WorldPrimitive> primitives;

    // Every triangle primitive (lists, strips and fans) of every instance,
    // placed by the instances' world transforms.
    static WorldGeometry from_scene(const scene::Scene& scene);

    // The same in each mesh's own space (instance transforms not applied),
    // to be placed later by the instances as they are then (a moved mirror).
    static WorldGeometry in_object_space(const scene::Scene& scene);

    // Object-space geometry moved to world space by instances[p.instance].world
    // for each primitive p; `instances` must be the scene's, possibly moved.
    WorldGeometry placed(const std::vector<scene::Instance>& instances) const;
    // primitives[i] of it alone (a split built a primitive at a time).
    WorldPrimitive placed_primitive(std::size_t i, const std::vector<scene::Instance>& instances) const;
    // extent_of(placed_primitive(i, instances)) without placing the whole
    // primitive: only its positions, into `positions` (kept by the caller
    // for the next primitive, so that a scene's extents allocate once).
    PrimitiveExtent placed_extent(std::size_t i, const std::vector<scene::Instance>& instances,
                                  std::vector<glm::vec3>& positions) const;
};

// Each primitive's triangles split into n x n smaller ones (a uniform
// barycentric grid), n = ceil(longest world edge of the primitive /
// max_edge_m), at most kMaxSubdivision. One n per primitive keeps shared
// edges split alike, so the surface stays watertight. max_edge_m <= 0: a copy.
inline constexpr int kMaxSubdivision = 64;
WorldGeometry subdivide(const WorldGeometry& geometry, float max_edge_m);
// One primitive of it, split as subdivide() splits it there (an unsplit
// one, n = 1, is returned as given: moved in, moved out).
WorldPrimitive subdivide(WorldPrimitive primitive, float max_edge_m);

// The most triangles a split may hold (SplitGeometry): 2^20, about 150 MB
// for the gathered vertices and as much for the GPU's copy (48-byte
// vertices, (n + 1)(n + 2) / 2 of them per n x n split triangle). With one n
// per primitive a large scene's long primitives (a city block's pavement, a
// ground plane) would split everything on them 64 x 64 times: 400 000
// triangles became 1.6e9 (24 GB) at the 0.25 m default edge.
inline constexpr std::size_t kMaxSplitTriangles = std::size_t(1) << 20;

PrimitiveExtent extent_of(const WorldPrimitive& primitive);

// The triangles and the vertices subdivide(geometry, max_edge_m) gives, from
// the geometry or from its primitives' extents.
std::size_t split_triangle_count(const WorldGeometry& geometry, float max_edge_m);
std::size_t split_vertex_count(const std::vector<PrimitiveExtent>& extents, float max_edge_m);

// max_edge_m, doubled until subdivide() gives at most max_triangles
// triangles (n only falls as the edge grows), or until no primitive is
// split (n = 1 everywhere: the geometry's own count, kept even when that is
// over). max_edge_m <= 0 (no split) is returned as is.
float edge_within_budget(const WorldGeometry& geometry, float max_edge_m,
                         std::size_t max_triangles = kMaxSplitTriangles);
float edge_within_budget(const std::vector<PrimitiveExtent>& extents, float max_edge_m,
                         std::size_t max_triangles = kMaxSplitTriangles);

} // namespace plan
