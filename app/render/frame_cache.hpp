// What every tile of one poster (poster.hpp) draws the same and need not
// draw again: kept by render_poster() for the poster's tiles, reached by
// the passes through PassContext::frame_cache. Only for one frame of one
// effect with one camera, scene and options: a new frame needs a new cache.
#pragma once

#include <gl/offscreen_target.hpp>

#include <glm/glm.hpp>

#include <optional>

namespace render {

struct FrameCache {
    // The curved mirror's patch atlas (curved_pass.cpp): planned for the
    // whole frame, so the same for every tile; up to 4096 x 4096 texels.
    std::optional<gl::OffscreenTarget> curved_atlas;
    // The mirror effect's reflection texture with the rectangle method
    // (mirror_pass.cpp): it spans the mirror rectangle, not the screen, so
    // every tile samples the same one; resolved colour only.
    std::optional<gl::OffscreenTarget> mirror_reflection;
};

} // namespace render
