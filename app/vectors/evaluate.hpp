// Request case -> answer, with the frustum library in double.
#pragma once

#include "vectors/request.hpp"

#include <frustum/crop.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace vectors {

// Normalized (|a, b, c| = 1), inward-positive planes (§3.1).
struct UnitPlanes {
    Vec4 left{0}, right{0}, bottom{0}, top{0}, near{0};
    std::optional<Vec4> far; // empty for an infinite far plane
};

// Everything the contract prints for a case that worked. Points are in the
// canonical homogeneous form of frustum::to_point (tolerance 1e-12): w = 1
// when finite, w = 0 and |xyz| = 1 at infinity.
struct Answer {
    Mat4 matrix{1}, inverse{1}; // w > 0 just inside the near face's centre (library convention)
    UnitPlanes planes;
    std::array<Vec4, 8> corners{}; // C1..C4 near, C5..C8 far (eq. 8)
    Vec4 center{0};                // D
    Vec4 eye{0};                   // O, on the near plane's negative side
    Vec4 vanishing_y{0};           // O1 = m1'
    Vec4 vanishing_x{0};           // O2 = m0'
    bool valid = false;            // §5.5, frustum::validate
    // Only when the request has "points": M * [p, 1] and the inside test.
    std::optional<std::vector<Vec4>> clip;
    std::optional<std::vector<bool>> inside;
    // Version 2, only when the request has "rects" / "boxes": the pixel
    // rectangle of each polygon (empty: nothing visible) and the cull word
    // ("outside", "intersect", "inside") of each box.
    std::optional<std::vector<std::optional<frustum::CropRect<double>>>> screen_rects;
    std::optional<std::vector<std::string>> cull;
};

struct Outcome {
    std::string id;
    std::optional<Answer> answer; // empty: ok = false
    std::string error;            // e.g. "camera.perspective: frustum::perspective(): near must be > 0 ..."
};

// Relative tolerance of the "inside" test: a point p is inside when every
// unit plane (n, d) has n . p + d >= -kInsideTolerance (|p| + |d|), |p| the
// Euclidean length (std::hypot, no overflow); the far plane only when finite.
inline constexpr double kInsideTolerance = 1e-6;

// camera -> compose with view (P * V) -> ops in order -> queries. Any
// library error, any number of the answer that is not finite, or a point
// that cannot be put in canonical form (|xyz| over- or underflows), makes
// the case ok = false; the error names where it arose ("camera.planes: ...",
// "view: ...", "ops[1].clip: ...", "points[0]: ...", "rects[0]: ...", "boxes[0]: ...",
// "planes: ...", "result: ...").
Outcome evaluate_case(const Case& c);

} // namespace vectors
