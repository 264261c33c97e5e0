#include "plan/split_geometry.hpp"

#include <utility>

namespace plan {
namespace {

// The split of `count` primitives, extent_at(i) giving the i-th's extent
// once placed and primitive_at(i) the i-th placed: the budget's edge from
// the extents, then each primitive placed, split and gathered in turn, so
// that neither the placed nor the split geometry is ever held whole beside
// the gathered vertices.
template <class ExtentAt, class PrimitiveAt>
SplitGeometry build_split(std::size_t count, const ExtentAt& extent_at, const PrimitiveAt& primitive_at,
                          float max_edge_m) {
    std::vector<PrimitiveExtent> extents;
    extents.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        extents.push_back(extent_at(i));
    }
    SplitGeometry out;
    out.max_edge_m = edge_within_budget(extents, max_edge_m);
    out.vertices.reserve(split_vertex_count(extents, out.max_edge_m));
    out.bases.reserve(count);
    out.split.primitives.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        WorldPrimitive q = subdivide(primitive_at(i), out.max_edge_m);
        out.bases.push_back(static_cast<std::uint32_t>(out.vertices.size()));
        out.vertices.insert(out.vertices.end(), q.vertices.begin(), q.vertices.end());
        q.vertices = {};
        out.split.primitives.push_back(std::move(q));
    }
    return out;
}

} // namespace

SplitGeometry SplitGeometry::build(const WorldGeometry& placed, float max_edge_m) {
    return build_split(
        placed.primitives.size(), [&](std::size_t i) { return extent_of(placed.primitives[i]); },
        [&](std::size_t i) -> const WorldPrimitive& { return placed.primitives[i]; }, max_edge_m);
}

SplitGeometry SplitGeometry::build(const WorldGeometry& object_space, const std::vector<scene::Instance>& instances,
                                   float max_edge_m) {
    // The extents place only positions (into one reused buffer); the split
    // places each primitive whole once, as it is split.
    std::vector<glm::vec3> positions;
    return build_split(
        object_space.primitives.size(),
        [&](std::size_t i) { return object_space.placed_extent(i, instances, positions); },
        [&](std::size_t i) { return object_space.placed_primitive(i, instances); }, max_edge_m);
}

const SplitGeometry& SplitGeometryCache::get(const std::vector<scene::Instance>& instances, float max_edge_m) {
    bool same = built_ && max_edge_m == max_edge_m_ && instances.size() == worlds_.size();
    for (std::size_t i = 0; same && i < instances.size(); ++i) {
        same = instances[i].world == worlds_[i];
    }
    if (!same) {
        current_ = {}; // the old split goes before the new one is built
        current_ = SplitGeometry::build(object_space_, instances, max_edge_m);
        worlds_.clear();
        for (const scene::Instance& instance : instances) {
            worlds_.push_back(instance.world);
        }
        max_edge_m_ = max_edge_m;
        built_ = true;
    }
    return current_;
}

} // namespace plan
