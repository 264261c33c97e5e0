#include "plan/split_geometry.hpp"

#include <utility>

namespace plan {

SplitGeometry SplitGeometry::build(const WorldGeometry& placed, float max_edge_m) {
    SplitGeometry out;
    out.max_edge_m = edge_within_budget(placed, max_edge_m);
    out.split = subdivide(placed, out.max_edge_m);
    std::size_t count = 0;
    for (const WorldPrimitive& p : out.split.primitives) {
        count += p.vertices.size();
    }
    out.vertices.reserve(count);
    out.bases.reserve(out.split.primitives.size());
    for (const WorldPrimitive& p : out.split.primitives) {
        out.bases.push_back(static_cast<std::uint32_t>(out.vertices.size()));
        out.vertices.insert(out.vertices.end(), p.vertices.begin(), p.vertices.end());
    }
    return out;
}

const SplitGeometry& SplitGeometryCache::get(const std::vector<scene::Instance>& instances, float max_edge_m) {
    bool same = built_ && max_edge_m == max_edge_m_ && instances.size() == worlds_.size();
    for (std::size_t i = 0; same && i < instances.size(); ++i) {
        same = instances[i].world == worlds_[i];
    }
    if (!same) {
        current_ = SplitGeometry::build(object_space_.placed(instances), max_edge_m);
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
