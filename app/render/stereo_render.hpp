// Side-by-side stereo images with the Renderer: each eye's cameras
// (plan/stereo.hpp) rendered as their own frame, so the mirror, lens and
// tile effects run per eye, then the left eye's image and the right eye's
// placed side by side.
#pragma once

#include "render/renderer.hpp"
#include "plan/stereo.hpp"

#include <frustum/result.hpp>
#include <image/image.hpp>

namespace render {

// options.width_px is the whole image: two eyes of width_px / 2 each
// (width_px must be even); `cameras` are made for one eye's image
// (make_cameras() with width_px / 2). Errors: an odd width, the
// stereo_cameras() ones, the renderer's, e.g.
// "render::render_stereo(): the image width must be even (two eyes side by side), got 641 px".
frustum::Result<image::Image> render_stereo(const Renderer& renderer, plan::Effect effect, const plan::Cameras& cameras,
                                            const RenderOptions& options, const plan::StereoRig& rig);

} // namespace render
