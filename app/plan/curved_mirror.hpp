// The curved mirror of paper §4.3, without GL: a convex cap over the planar
// mirror's rectangle, split into G x G patches; per patch the target volume
// (four reflected side planes + the patch's near plane) and the frustum
// frustum::fit_volume() finds for it (origin O by gradient ascent of
// sum cos^2, started at intersect(T0, T1, T2); then §4 from planes).
//
// The cap: footprint point F(u, v) = P1 + u a1 + v a2 (u, v in [0, 1]),
// lifted along the footprint's normal n = unit(a1 x a2) by the height of a
// sphere (or, Cylinder, a cylinder whose axis runs along a2) that passes
// through the footprint's corners (Sphere) or its a2 edges (Cylinder) and
// bulges by `sagitta_m` at the centre. With curvature k = 1/R =
// 2 s / (d^2 + s^2) (d: half-diagonal, or |a1| / 2 for the cylinder) and rho
// the in-plane offset from the centre (its a1 part only for the cylinder):
//   h = s - k |rho|^2 / (1 + sqrt(1 - k^2 |rho|^2)),
//   normal = unit(n + k rho / sqrt(1 - k^2 |rho|^2)),
// which is exact for k = 0 (sagitta 0: the planar mirror itself).
#pragma once

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <frustum/volume_approximation.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace plan {

enum class CapShape { Sphere, Cylinder };

// "sphere", "cylinder" and back (empty for any other text).
std::string_view to_string(CapShape shape);
std::optional<CapShape> parse_cap_shape(std::string_view text);

// What the curved effect draws (RenderOptions::curved).
struct CurvedMirrorOptions {
    CapShape shape = CapShape::Sphere;
    float sagitta_m = 0.3f; // bulge towards the viewer at the centre; 0 = flat
    int patches = 4;        // G: the cap is split into G x G patches, 1..kMaxCurvedPatches
};

inline constexpr int kMaxCurvedPatches = 64;

struct CapPoint {
    glm::dvec3 position;
    glm::dvec3 normal; // unit, on the reflecting side
};

class CurvedMirror {
public:
    // Errors: a degenerate footprint, a sagitta < 0 or > d / 2 (the rim
    // would then tilt by more than 53 degrees; at s = d the cap is a
    // hemisphere and no longer a height field).
    static frustum::Result<CurvedMirror> create(const scene::MirrorRect& footprint, CapShape shape,
                                                double sagitta_m);

    CapPoint at(double u, double v) const;
    // The first point where the ray o + t dir (t > t_min) enters the cap
    // from its reflecting side: t and the cap's (u, v).
    struct Hit {
        double t;
        glm::dvec2 uv;
    };
    std::optional<Hit> intersect(const glm::dvec3& origin, const glm::dvec3& direction, double t_min) const;

    // The footprint's plane, positive on the reflecting side: every cap
    // point is on it or in front of it.
    glm::dvec3 base_normal() const { return n_; }
    glm::dvec3 base_center() const { return center_; }
    const scene::MirrorRect& footprint() const { return footprint_; }
    CapShape shape() const { return shape_; }
    double sagitta_m() const { return sagitta_; }
    double curvature() const { return k_; } // 1 / R, 0 when flat

private:
    CurvedMirror() = default;
    glm::dvec3 offset(double u, double v) const; // rho (curved part only) at (u, v)

    scene::MirrorRect footprint_{};
    CapShape shape_ = CapShape::Sphere;
    double sagitta_ = 0, k_ = 0;
    glm::dvec3 center_{0}, e1_{0}, e2_{0}, n_{0};
    double length1_ = 0, length2_ = 0; // |a1|, |a2|
};

// Patch (i, j) covers u in [i, i+1] / G and v in [j, j+1] / G. Seen from
// behind the mirror (from the patch frustum's origin, looking along n),
// a1 points left and a2 up, so the corners in frustum::VolumeTarget's
// order (top-left, top-right, bottom-right, bottom-left, clockwise) are
// (u1, v1), (u0, v1), (u0, v0), (u1, v0): the patch frustum is an ordinary,
// unmirrored view (no winding flip).
// - Side plane i passes through X_i and X_i+1 and contains r_i + r_i+1,
//   the sum of the eye's rays to those corners reflected about the cap's
//   normals there (r = d - 2 (d . N) N); t_i points into the patch volume.
//   Neighbouring patches share the plane of their common edge.
// - The near plane fits the four corners (normal = unit(diagonal x
//   diagonal), through their centroid), positive on the eye's side; the X_i
//   are the corners projected onto it (they move by < 1e-3 of the patch
//   size for the showcase's spherical cap; exactly 0 for a flat or
//   cylindrical cap, whose patch corners are coplanar).
frustum::VolumeTarget<double> patch_target(const CurvedMirror& mirror, const glm::dvec3& eye, int grid, int i, int j);

struct PatchFrustum {
    int i = 0, j = 0;
    std::string error;        // empty when the patch has a frustum
    glm::dvec3 origin{0};     // the optimized O
    double objective = 0;     // F(O) = sum cos^2, at most 4
    double start_objective = 0; // F at intersect(T0, T1, T2); NaN when they do not meet
                                // behind the near plane (fit_volume() then starts elsewhere)
    int iterations = 0;
    std::optional<frustum::MatrixPair<float>> pair; // ZeroToOne; empty when the patch failed
};

struct CurvedPlan {
    int grid = 1;
    std::vector<PatchFrustum> patches; // G x G, index j * G + i
    int failed = 0;                    // patches without a frustum
};

// Every patch's target fitted. Empty when the eye is not in front of the
// footprint plane (nothing to reflect, as for the planar mirror). The far
// plane of each frustum lies beyond every corner of `bounds` it could show
// (when fit_volume()'s does not, the pair is rebuilt from its own planes
// with frustum::from_planes() and a far point that does). A patch fails
// when the eye sees it from behind, when the fit fails, or when F < 3.9.
frustum::Result<std::optional<CurvedPlan>> plan_curved_mirror(const CurvedMirror& mirror, const glm::dvec3& eye,
                                                              const scene::Bounds& bounds, int grid);

} // namespace plan
