// The non-affine split within a triangle budget (plan/world_geometry.hpp,
// issue 36's large scene): one n per primitive splits everything on a long
// primitive 64 x 64 times, so the edge grows (doubling) until the split
// holds at most kMaxSplitTriangles; the showcase, far under it, keeps the
// edge it asks for.
#include "showcase.hpp"

#include <plan/split_geometry.hpp>
#include <plan/world_geometry.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstddef>
#include <vector>

namespace {

// One primitive: a rows x rows grid of quads (2 triangles each) over a
// side_m x side_m square, so its longest edge is a quad's diagonal while
// the primitive spans side_m.
plan::WorldPrimitive grid(int rows, float side_m) {
    plan::WorldPrimitive p;
    const float step = side_m / static_cast<float>(rows);
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i <= rows; ++i) {
            plan::WorldVertex v;
            v.position = glm::vec3(static_cast<float>(i) * step, 0.0f, static_cast<float>(j) * step);
            p.vertices.push_back(v);
        }
    }
    const auto at = [rows](int i, int j) { return static_cast<std::uint32_t>(j * (rows + 1) + i); };
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < rows; ++i) {
            p.indices.insert(p.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            p.indices.insert(p.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return p;
}

} // namespace

TEST_SUITE("plan") {

TEST_CASE("the showcase's non-affine split keeps the 0.25 m edge: it is within the triangle budget") {
    const auto world = plan::WorldGeometry::from_scene(render_test::showcase());
    const std::size_t count = plan::split_triangle_count(world, 0.25f);
    MESSAGE("showcase split at 0.25 m: " << count << " triangles (budget " << plan::kMaxSplitTriangles << ")");
    CHECK(count <= plan::kMaxSplitTriangles);
    CHECK(plan::edge_within_budget(world, 0.25f) == 0.25f);
    const auto split = plan::SplitGeometry::build(world, 0.25f);
    CHECK(split.max_edge_m == 0.25f);
}

TEST_CASE("a long primitive's split grows the edge until it fits the budget, and no further") {
    plan::WorldGeometry world;
    // 100 x 100 quads over 400 m: 20000 triangles with 5.7 m diagonals; at
    // 0.25 m each would split 23 x 23 times (10.6 million triangles).
    world.primitives.push_back(grid(100, 400.0f));
    REQUIRE(plan::split_triangle_count(world, 0.25f) > plan::kMaxSplitTriangles);
    const float edge_m = plan::edge_within_budget(world, 0.25f);
    const std::size_t count = plan::split_triangle_count(world, edge_m);
    MESSAGE("edge " << edge_m << " m: " << count << " triangles");
    CHECK(count <= plan::kMaxSplitTriangles);
    CHECK(plan::split_triangle_count(world, edge_m / 2.0f) > plan::kMaxSplitTriangles); // the first that fits
    const auto split = plan::SplitGeometry::build(world, 0.25f);
    CHECK(split.max_edge_m == edge_m);
    std::size_t built = 0;
    for (const plan::WorldPrimitive& p : split.split.primitives) {
        built += p.indices.size() / 3;
    }
    CHECK(built == count);
    // A small budget: once nothing is split the geometry's own count stays,
    // even above it.
    const float unsplit_m = plan::edge_within_budget(world, 0.25f, 1000);
    CHECK(plan::split_triangle_count(world, unsplit_m) == 20000);
    // No split asked for: none.
    CHECK(plan::edge_within_budget(world, 0.0f) == 0.0f);
}

TEST_CASE("a split built from object space and the instances equals the split of the placed geometry") {
    // Two instances of one grid: one scaled 30x (its edges split), one
    // mirrored (its winding reversed), as a moved mirror rebuilds the split.
    plan::WorldGeometry object_space;
    for (int instance : {0, 1}) {
        plan::WorldPrimitive p = grid(4, 1.0f);
        p.instance = instance;
        p.material = 3 + instance;
        object_space.primitives.push_back(p);
    }
    std::vector<scene::Instance> instances(2);
    instances[0].world = glm::scale(glm::mat4(1.0f), glm::vec3(30.0f, 1.0f, 30.0f));
    instances[1].world = glm::translate(glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)), glm::vec3(2, 0, 0));
    const auto direct = plan::SplitGeometry::build(object_space.placed(instances), 0.25f);
    const auto streamed = plan::SplitGeometry::build(object_space, instances, 0.25f);
    CHECK(streamed.max_edge_m == direct.max_edge_m);
    CHECK(streamed.bases == direct.bases);
    REQUIRE(streamed.vertices.size() == direct.vertices.size());
    CHECK(streamed.vertices.size() > object_space.primitives[0].vertices.size() * 2); // instance 0 was split
    bool same_vertices = true;
    for (std::size_t v = 0; v < direct.vertices.size(); ++v) {
        same_vertices = same_vertices && streamed.vertices[v].position == direct.vertices[v].position &&
                        streamed.vertices[v].normal == direct.vertices[v].normal;
    }
    CHECK(same_vertices);
    REQUIRE(streamed.split.primitives.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(streamed.split.primitives[i].indices == direct.split.primitives[i].indices);
        CHECK(streamed.split.primitives[i].material == object_space.primitives[i].material);
        CHECK(streamed.split.primitives[i].instance == object_space.primitives[i].instance);
    }
}

} // TEST_SUITE
