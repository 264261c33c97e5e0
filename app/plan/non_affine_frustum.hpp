// The crossed-slits frustum of paper §6 for a camera: its options and its
// six planes (GL-free; non_affine_pass.hpp draws with it).
#pragma once

#include <frustum/depth_range.hpp>
#include <frustum/matrix_pair.hpp>
#include <frustum/non_affine.hpp>
#include <frustum/result.hpp>

namespace plan {

struct NonAffineOptions {
    float slit_depth_m = 2.6f;  // left and right planes meet this far in front of the eye
    float pivot_depth_m = 8.0f; // ... and still cut the camera's side planes at this depth
    float max_edge_m = 0.25f;   // subdivision target in world space; 0 = none
    bool cull = true;           // false: the naive eq. 36 (for comparison only)
    float guard_m = 0.01f;      // a vertex is degenerate when a denominator is >= -guard_m
};

// The crossed-slits frustum of `camera` (perspective, finite far plane):
// outward unit planes as NonAffineFrustum wants them. Errors name the
// values: 0 < slit_depth_m < pivot_depth_m < the camera's far distance.
frustum::Result<frustum::NonAffineFrustum<float>> crossed_slits_frustum(const frustum::MatrixPair<float>& camera,
                                                                        const NonAffineOptions& options,
                                                                        frustum::DepthRange depth);

} // namespace plan
