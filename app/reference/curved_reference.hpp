// The per-pixel reference for the curved mirror: a CPU ray tracer. Each
// pixel's ray meets the exact cap (CurvedMirror::intersect), reflects about
// the exact normal there, and the reflected ray is shaded with the model of
// shaders/scene.frag (base colour x vertex colour x (ambient + diffuse
// max(n.l, 0)), sRGB-encoded, 8 bits; back faces of single-sided materials
// are invisible, as GL culls them). No BVH: a bounding-box test per
// instance, then every triangle.
#pragma once

#include "plan/curved_mirror.hpp"
#include "render/pass_context.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <image/image.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <vector>

namespace reference {

struct TraceSettings {
    render::Lighting lighting;
    glm::vec4 clear_color = render::kClearColor;
    glm::vec3 tint{1.0f}; // multiplies the 8-bit reflection, as the composite does
};

struct TracedFrame {
    image::Image picture;        // width x height RGBA8, rows top to bottom
    std::vector<bool> on_mirror; // per pixel (row-major from the top): the ray meets the cap first
    int mirror_pixels = 0;
};

// The frame as `camera` (any depth range) sees `scene` with the cap in
// place of the planar mirror's surface (scene.mirror->instance is skipped).
// Materials are drawn opaque, as the scene pass draws them. Errors: a
// material with a texture (the reference does not sample textures).
frustum::Result<TracedFrame> trace_curved_frame(const scene::Scene& scene, const plan::CurvedMirror& mirror,
                                                const frustum::MatrixPair<float>& camera, int width_px, int height_px,
                                                const TraceSettings& settings);

// The patch approximation's own error, free of sampling: over the pixels
// whose ray meets the cap (occluders ignored), the angle between the ray
// reflected exactly at the cap point S and the ray the composite looks up,
// O -> S from the patch frustum's origin. Patches without a frustum are
// left out.
struct RayAngleError {
    int pixels = 0;
    double mean_deg = 0, max_deg = 0;
};
RayAngleError lookup_ray_error(const plan::CurvedMirror& mirror, const plan::CurvedPlan& plan,
                               const frustum::MatrixPair<float>& camera, int width_px, int height_px);

// Rendered vs traced over the pixels of `mask` (image::compare_masked(),
// RGB). Precondition: both images and the mask have the same size (else it
// aborts with compare_masked()'s error).
struct MirrorError {
    int pixels = 0;
    double mean_abs = 0;      // mean |a - b| over the RGB channels, 0..255
    int max_abs = 0;          // largest channel difference
    double fraction_over = 0; // pixels with some channel differing by more than the threshold
};
MirrorError compare_on_mask(const image::Image& rendered, const image::Image& traced, const std::vector<bool>& mask,
                            int threshold);

} // namespace reference
