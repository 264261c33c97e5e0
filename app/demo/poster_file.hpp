// One effect as a poster file (issue 36): render::render_poster()'s rows of
// tiles streamed into an image::PngStream as they finish, a thumbnail for
// the contact sheet box-filtered from the same rows, and a progress line
// for long renders. Holds one row of tiles and the thumbnail, never the
// whole image. Prints nothing.
#pragma once

#include <frustum/result.hpp>
#include <image/image.hpp>
#include <render/poster.hpp>
#include <render/renderer.hpp>

#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace demo {

// The largest direct render per side (render::Renderer::render(), one
// target): larger frames, or any with --poster-tile, are posters.
inline constexpr int kMaxDirectSidePx = 8192;

// The contact sheet's cell of a poster: its longer side at most this.
inline constexpr int kPosterThumbnailSidePx = 1024;

// Time spent, as the wall clock and as the process's CPU time
// (std::clock(): every thread's, llvmpipe's included), which a loaded
// machine does not stretch as it stretches the wall clock.
struct Spent {
    double wall_s = 0.0;
    double cpu_s = 0.0;
};

// Where the time of a poster went.
struct PosterTiming {
    Spent rendering;      // drawing the tiles (each ended by a glFinish), planning included
    Spent read_back;      // resolving each tile's samples and reading it into the row of tiles
    Spent compression;    // the rows' PNG compression and the thumbnail (the sink)
    double total_s = 0.0; // wall clock, start to finish
};

struct PosterFile {
    image::Image thumbnail; // at most kPosterThumbnailSidePx per side
    PosterTiming timing;
};

struct PosterJob {
    plan::Effect effect = plan::Effect::Plain;
    render::PosterLayout layout; // render::stereo_poster_layout() with `stereo`
    // Set: both eyes side by side (render::render_stereo_poster(), the
    // cameras made for one eye's image), as a direct stereo render.
    std::optional<plan::StereoRig> stereo;
    std::string path;
    int zlib_level = 3; // image::kStreamZlibLevel
    // "mirror: tile 12/64, 3.4 Mpx/s, 41 s left": after the first second, at
    // most once a second; "" when the poster is done. Empty: no progress.
    std::function<void(std::string_view)> status;
};

// The file appears only when complete (image::PngStream).
frustum::Result<PosterFile> write_poster(const render::Renderer& renderer, const plan::Cameras& cameras,
                                         const render::RenderOptions& options, const PosterJob& job);

} // namespace demo
