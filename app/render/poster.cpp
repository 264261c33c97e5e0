#include "render/poster.hpp"

#include "render/frame_window.hpp"

#include <gl/offscreen_target.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

// Why kMaxPosterSidePx is 65536 (2^16) per side:
// - Float crop offsets, the binding reason: a tile's pair is the whole
//   frame's cropped (eq. 14-15, in double, then rounded to float) and the
//   GPU multiplies it with float vertices. The worst of 20000 points over
//   the showcase's view lands, in its 4096^2 tile, this far from its
//   double-precision place (test_poster_slow, "the float crop at 65536"):
//     16384: 0.057 px, 32768: 0.16 px, 65536: 0.27 px, 131072: 0.59 px
//   (the frame drawn whole in float: 0.04, 0.08, 0.16, 0.32 px). Up to
//   65536 two tiles sharing an edge place it less than a pixel apart; at
//   131072 they may not, and a seam could show.
// - Time: llvmpipe on this (shared, 2-core) machine draws posters with 4x
//   MSAA at 2.8 (portal) to 9.4 (mirror) Mpx/s at 16384^2, 3.0 to 19.6 at
//   4096^2 in 512^2 tiles (test_poster_slow), so 65536^2 (4295 Mpx) is 8
//   to 26 minutes of rendering before compression, and every doubling of
//   the side quadruples it.
// - Sizes: 65536^2 x 4 bytes = 16 GiB of pixels: every byte count here is
//   std::size_t, and 65536 fits the int pixel coordinates of GL
//   (glViewport, glScissor) and of frustum::Tile with room to spare.
namespace render {
namespace {

constexpr const char* kLayout = "render::poster_layout()";
constexpr const char* kRender = "render::render_poster()";

// The largest tile side used without --poster-tile, whatever the context allows.
constexpr int kMaxAutoTileSidePx = 4096;
// What a poster holds for its tiles, whatever its size: one tile's target
// (with 4x MSAA llvmpipe keeps its colour and depth samples in RAM: 32
// bytes a pixel) plus one row of tiles (frame width x tile height, RGBA8).
// The tile height follows from it: 4096 x 256 tiles for a 4096-wide frame
// (32 + 4 MiB), 4096 x 192 at 16384, 4096 x 144 at 32768, 4096 x 96 at
// 65536, so that a poster's memory does not grow with its width any more
// than with its height; and the tile's own fixed cost (making the target
// and first touching its samples: 0.43 CPU s for 4096 x 1024 on this
// machine, 0.1 for 4096 x 256) stays small (docs/performance.md, "Posters").
constexpr std::int64_t kTileBytesPerPx = 4 * 8;
constexpr std::int64_t kPosterBudgetBytes = std::int64_t(36) << 20;
// Tile heights are cut to a multiple of this (when taller): the seam and
// downsampling tests divide a poster's tiles by 2 and 4.
constexpr int kTileHeightStepPx = 16;

std::string size_text(int width_px, int height_px) {
    return std::to_string(width_px) + "x" + std::to_string(height_px);
}

// The context's largest target: renderbuffer, texture and viewport limits.
std::pair<int, int> largest_target(const gl::Functions& fn) {
    GLint renderbuffer = 0, texture = 0, viewport[2] = {0, 0};
    fn.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    fn.GetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    fn.GetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    const int side = std::min(renderbuffer, texture);
    return {std::min(side, static_cast<int>(viewport[0])), std::min(side, static_cast<int>(viewport[1]))};
}

frustum::Status check_frame_size(int width_px, int height_px, const char* where) {
    if (width_px < 1 || height_px < 1 || width_px > kMaxPosterSidePx || height_px > kMaxPosterSidePx) {
        return frustum::Error{std::string(where) + ": size must be 1x1 to " +
                              size_text(kMaxPosterSidePx, kMaxPosterSidePx) + ", got " +
                              size_text(width_px, height_px)};
    }
    return {};
}

// The automatic tile's height for tiles tile_width_px wide in rows of tiles
// row_width_px wide: within the budget, the frame and the context.
int auto_tile_height(int row_width_px, int tile_width_px, int height_px, int largest_h) {
    const std::int64_t by_budget =
        kPosterBudgetBytes / (std::int64_t(tile_width_px) * kTileBytesPerPx + std::int64_t(row_width_px) * 4);
    std::int64_t h = std::min({by_budget, std::int64_t(height_px), std::int64_t(largest_h),
                               std::int64_t(kMaxAutoTileSidePx)});
    if (h > kTileHeightStepPx && h < height_px) {
        h -= h % kTileHeightStepPx;
    }
    return static_cast<int>(std::max<std::int64_t>(1, h));
}

} // namespace

frustum::Result<PosterLayout> poster_layout(const gl::Functions& fn, int width_px, int height_px,
                                            std::optional<std::pair<int, int>> requested_tile_px) {
    if (auto status = check_frame_size(width_px, height_px, kLayout); !status) {
        return status.take_error();
    }
    const auto [largest_w, largest_h] = largest_target(fn);
    PosterLayout layout{width_px, height_px, 0, 0};
    if (requested_tile_px) {
        const auto [w, h] = *requested_tile_px;
        if (w < 1 || h < 1) {
            return frustum::Error{std::string(kLayout) + ": tile must be at least 1x1, got " + size_text(w, h)};
        }
        if (w > largest_w || h > largest_h) {
            return frustum::Error{std::string(kLayout) + ": tile " + size_text(w, h) +
                                  " exceeds the context's largest target " + size_text(largest_w, largest_h)};
        }
        layout.tile_width_px = std::min(w, width_px);
        layout.tile_height_px = std::min(h, height_px);
        return layout;
    }
    layout.tile_width_px = std::min({width_px, largest_w, kMaxAutoTileSidePx});
    layout.tile_height_px = auto_tile_height(width_px, layout.tile_width_px, height_px, largest_h);
    return layout;
}

namespace {

// One frame of a poster: its cameras and where it lies in the poster's
// rows (x_px, width_px; the whole height). A mono poster has one, a stereo
// poster one per eye.
struct PosterView {
    const plan::Cameras* cameras = nullptr;
    int x_px = 0;
    int width_px = 0;
};

frustum::Status check_tile(const PosterLayout& layout, int frame_width_px, const char* where) {
    if (auto status = check_frame_size(layout.width_px, layout.height_px, where); !status) {
        return status;
    }
    if (layout.tile_width_px < 1 || layout.tile_height_px < 1 || layout.tile_width_px > frame_width_px ||
        layout.tile_height_px > layout.height_px) {
        return frustum::Error{std::string(where) + ": tile must be 1x1 to the frame's " +
                              size_text(frame_width_px, layout.height_px) + ", got " +
                              size_text(layout.tile_width_px, layout.tile_height_px)};
    }
    return {};
}

// The rows of tiles of every view side by side, top to bottom.
frustum::Status draw_poster(const Renderer& renderer, plan::Effect effect, const std::vector<PosterView>& views,
                            const RenderOptions& options, const PosterLayout& layout, const PosterRowSink& sink,
                            const PosterProgress& progress, const PosterSteps& steps) {
    const gl::Functions& fn = renderer.functions();
    auto samples = gl::choose_samples(fn, options.msaa_samples);
    if (!samples) {
        return samples.take_error_in(kRender);
    }
    const int rows = (layout.height_px + layout.tile_height_px - 1) / layout.tile_height_px;
    int columns = 0; // of all the views
    for (const PosterView& view : views) {
        columns += (view.width_px + layout.tile_width_px - 1) / layout.tile_width_px;
    }
    const int total = columns * rows;
    // A few tile sizes (the last column and row are cut): a target is made
    // again only when the size changes.
    std::optional<gl::OffscreenTarget> target;
    // What every tile of one view draws the same (the curved mirror's
    // patch views, the rectangle method's reflection): one cache per view.
    std::vector<FrameCache> caches(views.size());
    // One row of tiles, kept from row to row (cut for the last one): every
    // tile is read back into its columns, so the row needs no clearing.
    image::Image strip{layout.width_px, 0, {}};
    int done = 0;
    for (int row = 0; row < rows; ++row) {
        const int top_px = row * layout.tile_height_px; // from the frame's top
        const int height_px = std::min(layout.tile_height_px, layout.height_px - top_px);
        strip.height = height_px;
        strip.rgba.resize(static_cast<std::size_t>(layout.width_px) * static_cast<std::size_t>(height_px) * 4);
        for (std::size_t v = 0; v < views.size(); ++v) {
            const PosterView& view = views[v];
            for (int x_px = 0; x_px < view.width_px; x_px += layout.tile_width_px) {
                const int width_px = std::min(layout.tile_width_px, view.width_px - x_px);
                if (!target || target->width() != width_px || target->height() != height_px) {
                    target.reset(); // free the old one first
                    auto made = gl::OffscreenTarget::create(fn, {width_px, height_px, gl::ColorStorage::Renderbuffer,
                                                                 gl::DepthFormat::Depth24, *samples});
                    if (!made) {
                        return made.take_error_in(kRender);
                    }
                    target = std::move(*made);
                }
                // GL counts rows from the bottom.
                if (steps) {
                    steps(PosterStep::Draw);
                }
                const FrameWindow window{
                    view.width_px, layout.height_px,
                    plan::PixelRect{x_px, layout.height_px - top_px - height_px, width_px, height_px}};
                if (auto status = renderer.render_into(effect, *view.cameras, options, *target, window, &caches[v]);
                    !status) {
                    return status;
                }
                if (steps) {
                    fn.Finish();
                    steps(PosterStep::ReadBack);
                }
                if (auto read = target->read_rgba8_into(strip, view.x_px + x_px); !read) {
                    return read.take_error_in(kRender);
                }
                ++done;
                if (progress) {
                    progress(done, total);
                }
            }
        }
        if (auto status = sink(strip, top_px); !status) {
            return status;
        }
    }
    return {};
}

std::string odd_width(const char* where, int width_px) {
    return std::string(where) + ": the width must be even (two eyes side by side), got " + std::to_string(width_px) +
           " px";
}

} // namespace

frustum::Status render_poster(const Renderer& renderer, plan::Effect effect, const plan::Cameras& cameras,
                              const RenderOptions& options, const PosterLayout& layout, const PosterRowSink& sink,
                              const PosterProgress& progress, const PosterSteps& steps) {
    if (auto status = check_tile(layout, layout.width_px, kRender); !status) {
        return status;
    }
    return draw_poster(renderer, effect, {PosterView{&cameras, 0, layout.width_px}}, options, layout, sink, progress,
                       steps);
}

frustum::Result<PosterLayout> stereo_poster_layout(const gl::Functions& fn, int width_px, int height_px,
                                                   std::optional<std::pair<int, int>> requested_tile_px) {
    constexpr const char* kStereoLayout = "render::stereo_poster_layout()";
    if (width_px % 2 != 0) {
        return frustum::Error{odd_width(kStereoLayout, width_px)};
    }
    auto layout = poster_layout(fn, width_px, height_px, requested_tile_px);
    if (!layout) {
        return layout.take_error();
    }
    layout->tile_width_px = std::min(layout->tile_width_px, width_px / 2);
    if (!requested_tile_px) {
        // The tile budget, as a mono poster's tiles have it.
        layout->tile_height_px =
            auto_tile_height(width_px, layout->tile_width_px, height_px, largest_target(fn).second);
    }
    return layout;
}

frustum::Status render_stereo_poster(const Renderer& renderer, plan::Effect effect, const plan::Cameras& cameras,
                                     const RenderOptions& options, const plan::StereoRig& rig,
                                     const PosterLayout& layout, const PosterRowSink& sink,
                                     const PosterProgress& progress, const PosterSteps& steps) {
    constexpr const char* kStereo = "render::render_stereo_poster()";
    if (layout.width_px % 2 != 0) {
        return frustum::Error{odd_width(kStereo, layout.width_px)};
    }
    const int eye_width_px = layout.width_px / 2;
    if (auto status = check_tile(layout, eye_width_px, kStereo); !status) {
        return status;
    }
    auto eyes = plan::stereo_cameras(cameras, rig);
    if (!eyes) {
        return frustum::Error{eyes.error()};
    }
    return draw_poster(renderer, effect,
                       {PosterView{&eyes->left, 0, eye_width_px}, PosterView{&eyes->right, eye_width_px, eye_width_px}},
                       options, layout, sink, progress, steps);
}

} // namespace render
