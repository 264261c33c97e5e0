// The math of the mirror effect, without GL: the mirror's plane, the screen
// rectangle it covers, and the camera its reflection is rendered with.
#pragma once

#include "plan/effect.hpp"

#include <frustum/crop.hpp>
#include <frustum/matrix_pair.hpp>
#include <frustum/plane.hpp>
#include <frustum/result.hpp>
#include <scene/scene.hpp>

#include <optional>
#include <vector>

namespace plan {

// Whole pixels, offset from the bottom-left corner (glViewport's and
// frustum::CropRect's convention, docs/errata.md erratum 1).
struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;
};

// The mirror's plane, unit normal normalize(cross(a1, a2)): positive on the
// reflecting side (scene.hpp), which is where the eye must be.
frustum::Plane<float> mirror_plane(const scene::MirrorRect& mirror);

// The smallest rectangle of whole pixels holding `r`, inside its image
// (floor / ceil, clamped to full_width x full_height); empty when no pixel
// is left.
std::optional<frustum::CropRect<float>> whole_pixels(const frustum::CropRect<float>& r);

// A rectangle of whole pixels (whole_pixels()) as a PixelRect.
PixelRect pixel_rect(const frustum::CropRect<float>& whole);

// The whole pixels of a width_px x height_px image that `camera` sees of a
// planar convex polygon: frustum::screen_rect() (the polygon clipped by the
// frustum's planes in clip space, near first, so that a point behind the
// eye is never projected), rounded out to whole pixels (floor / ceil).
// Empty when nothing of it is seen (or only an edge), and when
// screen_rect() refuses it: fewer than 3 points, a point not finite, a
// size not > 0.
std::optional<PixelRect> pixels_seen(const frustum::MatrixPair<float>& camera, const std::vector<glm::vec3>& polygon,
                                     int width_px, int height_px);

// The pixels the mirror quad can cover: pixels_seen() of its corners.
std::optional<PixelRect> mirror_screen_rect(const scene::MirrorRect& mirror, const frustum::MatrixPair<float>& camera,
                                            int width_px, int height_px);

struct ReflectionView {
    // ZeroToOne; renders the reflection texture and, in the composite
    // shader, maps a world point on the mirror to its texture coordinates.
    frustum::MatrixPair<float> pair;
    int texture_width_px = 0, texture_height_px = 0;
    // Oblique / ReflectOnly: the texture covers exactly these screen pixels.
    PixelRect screen_rect;
};

// The reflection camera for `method` (see effect.hpp):
// - Oblique: frustum::mirror(camera, plane) (§5.2: R of eq. 16, then the
//   mirror plane as oblique near plane, eq. 24-27 with docs/errata.md erratum 2),
//   cropped (§5.1) to mirror_screen_rect(). R fixes every point of the plane,
//   so on the mirror the reflected pair maps world to clip x, y, w exactly as
//   the camera does: texel (i, j) of a texture the size of the rectangle is
//   screen pixel (x + i, y + j).
// - ReflectOnly: frustum::reflect() then the same crop (no oblique plane).
// - Rectangle: frustum::mirror_rectangle(MirrorFit::Exact) from the camera's
//   eye; far reaches past every corner of `bounds`. Its texture spans the
//   whole mirror (x along a2, y along a1), sized by the longest on-screen
//   length of the mirror's edges.
// Empty when the mirror is off-screen or seen from behind (or edge-on).
frustum::Result<std::optional<ReflectionView>> plan_reflection(const scene::MirrorRect& mirror,
                                                               const frustum::MatrixPair<float>& camera,
                                                               int width_px, int height_px, MirrorMethod method,
                                                               const scene::Bounds& bounds);

} // namespace plan
