// The non-affine pass's triangles (paper §6): the scene's object-space
// geometry placed by the instances and split to max_edge_m (subdivide()),
// with every primitive's vertices in one array ready for one vertex buffer.
// None of this depends on the camera, so it is built once and kept from frame
// to frame; only the degenerate-vertex cull of eq. 36 is per frame.
#pragma once

#include "plan/world_geometry.hpp"

#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace plan {

struct SplitGeometry {
    // Placed and subdivided: each primitive's indices (into its own
    // vertices, which are in `vertices` from bases[i], not here: one copy of
    // the split's vertices, not two), material and instance.
    WorldGeometry split;
    std::vector<WorldVertex> vertices;  // every primitive's vertices, in primitive order
    std::vector<std::uint32_t> bases;   // bases[i]: split.primitives[i]'s first vertex in `vertices`

    float max_edge_m = 0.0f;            // the edge split to: the one asked for, or longer (budget)

    // `placed` split to max_edge_m (<= 0: not split), or to the longer edge
    // that keeps it within kMaxSplitTriangles (edge_within_budget()), and
    // gathered a primitive at a time (the split is never held twice).
    static SplitGeometry build(const WorldGeometry& placed, float max_edge_m);
    // The same from object-space geometry and the instances that place it
    // (WorldGeometry::placed()), placed a primitive at a time.
    static SplitGeometry build(const WorldGeometry& object_space, const std::vector<scene::Instance>& instances,
                               float max_edge_m);

    // The vertices of split.primitives[i]: `vertices` from bases[i] to end_of(i).
    std::size_t end_of(std::size_t i) const {
        return i + 1 < bases.size() ? bases[i + 1] : vertices.size();
    }
};

// SplitGeometry for the instances as they are now, rebuilt only when an
// instance's world transform or the edge length differs from the last call
// (a moved mirror, another fit): the renderer's non-affine frames after the
// first skip the placement, the subdivision and the gathering.
class SplitGeometryCache {
public:
    explicit SplitGeometryCache(WorldGeometry object_space) : object_space_(std::move(object_space)) {}

    // `instances`: the scene's, possibly moved (WorldGeometry::placed()).
    const SplitGeometry& get(const std::vector<scene::Instance>& instances, float max_edge_m);

private:
    WorldGeometry object_space_;
    std::vector<glm::mat4> worlds_; // of the last build
    float max_edge_m_ = 0.0f;
    bool built_ = false;
    SplitGeometry current_;
};

} // namespace plan
