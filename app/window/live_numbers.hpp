// The numbers the panel shows for one frame, computed on the CPU from the
// frame's pairs with the same planning functions the renderer calls: the
// camera pair and |M M^-1 - I| (the analytic inverse's residual), the
// mirror's screen rectangle, and per pass the CPU time of the pair updates
// (plan_reflection for the mirror pass of the mirror, curved and frustum
// effects: reflect + oblique near plane + crop;
// place_facing_links + plan_view_tree for the recursion). Pure: no GL.
#pragma once

#include "window/frame.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/queries.hpp>
#include <plan/mirror_geometry.hpp>
#include <scene/scene.hpp>

#include <optional>
#include <string>
#include <vector>

namespace window {

struct PassTiming {
    std::string pass;    // "mirror pair (reflect + oblique clip + crop)"
    double cpu_us = 0.0; // one run, steady_clock
    std::string result;  // "64x40 px texture", "13 views", or the planner's error
};

struct LiveNumbers {
    frustum::MatrixPair<float> pair;  // the frame's main camera
    double residual = 0.0;            // max |(M M^-1 - I)_ij|, in double
    frustum::FrustumPlanes<float> planes; // normalized, inward-positive (§3.1)
    frustum::KeyPoints<float> points;     // corners C1..C8, eye O, centre D in canonical form
                                          // (to_point: w = 1, or w = 0 with |xyz| = 1 at infinity; §3.2)
    std::optional<plan::PixelRect> mirror_rect; // from the bottom-left; empty: none on screen
    std::vector<PassTiming> passes;
};

// max_ij |(M M^-1 - I)_ij| of `pair`, products in double.
double inverse_residual(const frustum::MatrixPair<float>& pair);

// The numbers of `frame` (one eye's for stereo) on `scene`.
LiveNumbers live_numbers(const Frame& frame, const scene::Scene& scene);

} // namespace window
