// Posters (paper §5.1): a frame of any size up to kMaxPosterSidePx per side,
// larger than one GPU target, rendered as crop tiles of ONE camera and handed
// to the caller one row of tiles at a time, top to bottom, so memory does not
// grow with the frame's height. Every effect is planned once for the whole
// frame (the mirror's reflection, the portal's views, the recursion levels,
// the curved patches, the lens tiles, the non-affine fit) and each tile draws
// its crop of that plan, so no seam and no per-tile change of a derived
// parameter shows.
#pragma once

#include "plan/stereo.hpp"
#include "render/renderer.hpp"

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <image/image.hpp>

#include <functional>
#include <optional>

namespace render {

// 65536 per side: see poster.cpp for why.
inline constexpr int kMaxPosterSidePx = 65536;

// The whole frame and the size of one tile (one GPU target); the tiles of
// the last column and row are cut to the frame (narrower or lower).
struct PosterLayout {
    int width_px = 0;
    int height_px = 0;
    int tile_width_px = 0;
    int tile_height_px = 0;
};

// The tile size for a width_px x height_px frame: the requested one
// (--poster-tile), else the largest the context's targets hold (at most
// 4096 wide) with the tile height cut so that one tile's multisampled
// target (32 bytes a pixel with 4x MSAA: llvmpipe holds the samples in RAM)
// and one row of tiles (width_px x tile_height_px RGBA8) stay within 36 MiB
// together, the height a multiple of 16: e.g. 4096 x 256 tiles for a
// 4096-wide frame, 4096 x 192 for 16384, 4096 x 144 for 32768, 4096 x 96 for
// 65536. The memory for the tiles does not grow with the frame.
// A requested tile is cut to the frame.
// Errors name the value and the limit, e.g.
// "render::poster_layout(): tile 9000x512 exceeds the context's largest target 8192x8192".
frustum::Result<PosterLayout> poster_layout(const gl::Functions& fn, int width_px, int height_px,
                                            std::optional<std::pair<int, int>> requested_tile_px = {});

// Receives each finished row of tiles: `rows` is layout.width_px wide and as
// high as that row of tiles, its top row is the frame's row `top_px`. An
// error stops the poster and is returned by render_poster().
using PosterRowSink = std::function<frustum::Status(const image::Image& rows, int top_px)>;

// Called after each tile with the tiles done so far and in all.
using PosterProgress = std::function<void(int tiles_done, int tiles_total)>;

// Told as each tile's drawing starts and as its read-back starts (after a
// glFinish, so that the drawing is done by then): a caller times the two apart.
enum class PosterStep { Draw, ReadBack };
using PosterSteps = std::function<void(PosterStep)>;

// Renders `effect` as a layout.width_px x layout.height_px frame
// (options.width_px / height_px are ignored; options.msaa_samples as in
// Renderer::render()); `cameras` are made for the whole frame's aspect
// ratio. Each tile is multisampled and resolved as a direct render is, and
// is Renderer::render_into() with its FrameWindow: the effect planned for the
// whole frame, the tile drawing its crop. One view only (cameras.main, and
// cameras.overview for the frustum effect): a stereo pair is two posters, so
// a caller refuses stereo above one target or renders each eye's cameras
// as a poster of its own. Errors: a layout outside 1..kMaxPosterSidePx or a
// tile larger than the frame, a target the context cannot make, a pass's
// error, the sink's error.
frustum::Status render_poster(const Renderer& renderer, plan::Effect effect, const plan::Cameras& cameras,
                              const RenderOptions& options, const PosterLayout& layout,
                              const PosterRowSink& sink, const PosterProgress& progress = {},
                              const PosterSteps& steps = {});

// A stereo poster's layout: poster_layout() of the whole layout (both eyes:
// the row budget counts the whole width), the tile width then cut to one
// eye's (width_px / 2), so that no tile straddles the eyes, and an automatic
// tile's height then as high as the same budget allows (2048 x 448 for a
// 4096-wide pair). Errors: the
// poster_layout() ones, an odd width, e.g.
// "render::stereo_poster_layout(): the width must be even (two eyes side by side), got 9001 px".
frustum::Result<PosterLayout> stereo_poster_layout(const gl::Functions& fn, int width_px, int height_px,
                                                   std::optional<std::pair<int, int>> requested_tile_px = {});

// Stereo as a poster, in the layout render_stereo() writes: the left eye's
// frame on the left half of the layout.width_px x layout.height_px image,
// the right eye's on the right half, each eye's frame (width_px / 2 x
// height_px) a poster of crop tiles of that eye's cameras (stereo_cameras()
// of `cameras`, which are made for one eye's image, as for
// render_stereo()), every effect planned once per eye for the eye's whole
// frame. Each row of tiles is the left eye's tiles then the right eye's,
// handed to `sink` as one full-width row; progress counts both eyes'
// tiles. Errors: render_poster()'s, an odd width, a tile wider than one
// eye, the stereo_cameras() ones.
frustum::Status render_stereo_poster(const Renderer& renderer, plan::Effect effect, const plan::Cameras& cameras,
                                     const RenderOptions& options, const plan::StereoRig& rig,
                                     const PosterLayout& layout, const PosterRowSink& sink,
                                     const PosterProgress& progress = {}, const PosterSteps& steps = {});

} // namespace render
