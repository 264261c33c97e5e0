// The lens effect (paper section 5.4): the frame drawn tile by tile, each
// tile through the frustum frustum::lens_tiles() builds for it (near plane =
// the camera's near plane = the refraction plane; side planes through the
// eye and the tile's corners moved by eq. 34), into the tile's viewport and
// scissor rectangle. Inside the lens radius the image is magnified, outside
// it eq. 34's power law gives barrel distortion.
#pragma once

#include "render/pass_context.hpp"

#include <frustum/lens.hpp>
#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <gl/offscreen_target.hpp>
#include <scene/scene.hpp>

#include <optional>

namespace render {

struct LensDraw {
    frustum::MatrixPair<float> camera; // perspective, finite far plane, no oblique near plane
    frustum::Lens<float> lens;         // on the camera's near plane (lens_on_near_plane())
    int grid = 16;                     // grid x grid tiles
    int skip_instance = -1;            // not drawn: the lens disc itself
};

// The scene's lens spot (assets/README.md, node "lens") seen from `camera`,
// as a lens on its near plane: the centre is where the ray from the eye to
// the spot's centre meets the near plane, the radius is the distance from
// there to where the ray to the spot's centre + radius x (the near plane's
// x axis) meets it. Without a spot: centred, radius a quarter of the near
// rectangle's half height. Errors: a spot behind the eye, power <= 0.
frustum::Result<frustum::Lens<float>> lens_on_near_plane(const frustum::MatrixPair<float>& camera,
                                                         const std::optional<scene::LensSpot>& spot, float power);

// Draws the whole frame into `frame` (left bound). Needs 1 <= grid <= the
// frame's width and height.
frustum::Status draw_lens_frame(const PassContext& ctx, const gl::OffscreenTarget& frame, const LensDraw& draw);

} // namespace render
