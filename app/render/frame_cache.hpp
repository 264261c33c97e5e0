// What every tile of one poster (poster.hpp) draws the same and need not
// draw again: kept by render_poster() for the poster's tiles, reached by
// the passes through PassContext::frame_cache. Only for one frame of one
// effect with one camera, scene and options: a new frame needs a new cache.
#pragma once

#include <gl/offscreen_target.hpp>

#include <glm/glm.hpp>

#include <memory>
#include <optional>

namespace render {

struct CurvedViews;     // curved_pass.hpp
struct NonAffineUpload; // non_affine_pass.hpp

struct FrameCache {
    FrameCache();
    ~FrameCache();
    FrameCache(FrameCache&&) noexcept;
    FrameCache& operator=(FrameCache&&) noexcept;

    // The curved mirror's patch views (curved_pass.hpp): planned for the
    // whole frame, so the same for every tile; only the views of the
    // patches the current row of tiles meets are alive.
    std::unique_ptr<CurvedViews> curved_views;
    // The mirror effect's reflection texture with the rectangle method
    // (mirror_pass.cpp): it spans the mirror rectangle, not the screen, so
    // every tile samples the same one; resolved colour only.
    std::optional<gl::OffscreenTarget> mirror_reflection;
    // The recursion views' drawing target (recursion_pass.cpp): multisampled
    // like the frame, as large as the largest tile so far; each view of each
    // tile draws into its bottom-left part and is blitted into a colour-only
    // texture of its own, so one multisampled target serves the whole poster.
    std::optional<gl::OffscreenTarget> recursion_canvas;
    // The non-affine pass's triangles on the GPU (non_affine_pass.cpp): the
    // eq. 36 cull is the whole frame's, so the tiles draw the same buffers.
    std::unique_ptr<NonAffineUpload> non_affine;
};

} // namespace render
