// A per-pixel reference for the non-affine effect, independent of the GPU
// path: ray casting on the CPU, in double precision.
//
// Inverting eq. 36 for one pixel is exact and cheap: u = d_l / (d_l + d_r)
// holds on the plane (1 - u) L - u R = 0 and v = d_t / (d_t + d_b) on
// (1 - v) T - v B = 0, so the points that map to the pixel centre (u, v) form
// the line where these two planes meet. Along it the visible surface is the
// hit with the smallest s = d_n / (d_n + d_f) among the points inside the
// frustum (every d_i <= 0; inside, every denominator is negative, so no hit
// on the degenerate set or its mirror-image branch can count). The hit is
// shaded as shaders/scene.frag does.
//
// Limits: one sample per pixel centre (no anti-aliasing, as the GPU frame);
// textures are not sampled (base colour x vertex colour only; the showcase
// has none); points and lines are not drawn; cost O(pixels x triangles).
#pragma once

#include "render/pass_context.hpp"
#include "plan/world_geometry.hpp"

#include <frustum/non_affine.hpp>
#include <image/image.hpp>

#include <glm/glm.hpp>

namespace reference {

// width_px x height_px, rows top to bottom, sRGB-encoded like the GPU frame.
image::Image ray_cast_non_affine(const plan::WorldGeometry& geometry, const frustum::NonAffineFrustum<float>& frustum,
                                 const render::Lighting& lighting, const glm::vec4& clear_color, int width_px,
                                 int height_px);

} // namespace reference
