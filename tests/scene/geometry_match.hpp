// Compares the triangles two loaded scenes draw, in world space, whatever
// the order of their vertices, triangles and nodes: what a compressed or
// quantized file must keep of its original. Test-only code.
#pragma once

#include <scene/scene.hpp>

#include <cstddef>
#include <string>

namespace scene_test {

struct GeometryDifference {
    std::size_t triangles_a = 0, triangles_b = 0;
    std::size_t unmatched = 0;      // triangles of a with no triangle of b within the position tolerance
    float max_position_m = 0.0f;    // over matched vertices, world space
    float max_normal = 0.0f;        // |n_a - n_b| of the unit world normals
    float max_uv = 0.0f;            // per component
    std::string first_unmatched;    // "triangle 12 at (x, y, z)" for a message
};

// Every triangle (TRIANGLES primitives of every instance) of `a` is matched
// to a distinct triangle of `b` with the same vertices in the same cyclic
// order (winding kept) and positions within `position_tolerance_m`; the
// differences of the matched ones are returned.
GeometryDifference compare_triangles(const scene::Scene& a, const scene::Scene& b, float position_tolerance_m);

} // namespace scene_test
