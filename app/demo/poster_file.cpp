#include "demo/poster_file.hpp"

#include <image/png_stream.hpp>
#include <image/thumbnail.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace demo {
namespace {

using Clock = std::chrono::steady_clock;

// A moment on both clocks of Spent.
struct Mark {
    Clock::time_point wall = Clock::now();
    std::clock_t cpu = std::clock();
};

void add_between(Spent& spent, const Mark& from, const Mark& to) {
    spent.wall_s += std::chrono::duration<double>(to.wall - from.wall).count();
    spent.cpu_s += static_cast<double>(to.cpu - from.cpu) / CLOCKS_PER_SEC;
}

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// "12/64 tiles, 3.4 Mpx/s, 41 s left"
std::string progress_text(int done, int total, double mpx_done, double elapsed_s) {
    const double rate = elapsed_s > 0.0 ? mpx_done / elapsed_s : 0.0;
    const double left_s = done > 0 ? elapsed_s * (total - done) / done : 0.0;
    char text[128];
    std::snprintf(text, sizeof text, "%d/%d tiles, %.1f Mpx/s, %.0f s left", done, total, rate, std::ceil(left_s));
    return text;
}

} // namespace

frustum::Result<PosterFile> write_poster(const render::Renderer& renderer, const plan::Cameras& cameras,
                                         const render::RenderOptions& options, const PosterJob& job) {
    const render::PosterLayout& layout = job.layout;
    auto stream = image::PngStream::open(job.path, layout.width_px, layout.height_px, job.zlib_level);
    if (!stream) {
        return stream.take_error();
    }
    image::Thumbnail thumbnail(layout.width_px, layout.height_px, kPosterThumbnailSidePx);
    PosterTiming timing;
    const Clock::time_point start = Clock::now();
    Clock::time_point last_status = start;
    const double tile_mpx = double(layout.tile_width_px) * layout.tile_height_px / 1e6;
    const double frame_mpx = double(layout.width_px) * layout.height_px / 1e6;

    // The time since `last` goes to what render_poster() was doing then.
    Mark last;
    Spent* doing = &timing.rendering;
    const auto mark = [&](Spent* next) {
        const Mark now;
        add_between(*doing, last, now);
        last = now;
        doing = next;
    };
    const render::PosterSteps steps = [&](render::PosterStep step) {
        mark(step == render::PosterStep::Draw ? &timing.rendering : &timing.read_back);
    };
    const render::PosterRowSink sink = [&](const image::Image& rows, int) -> frustum::Status {
        Spent* const was = doing;
        mark(&timing.compression);
        if (auto written = (*stream)->write_rows(rows); !written) {
            return written;
        }
        thumbnail.add_rows(rows);
        mark(was);
        return {};
    };
    const render::PosterProgress progress = [&](int done, int total) {
        if (!job.status || seconds_since(last_status) < 1.0) {
            return;
        }
        last_status = Clock::now();
        const double mpx_done = std::min(frame_mpx, done * tile_mpx);
        job.status(std::string(plan::to_string(job.effect)) + ": " +
                   progress_text(done, total, mpx_done, seconds_since(start)));
    };
    auto drawn = job.stereo ? render::render_stereo_poster(renderer, job.effect, cameras, options, *job.stereo,
                                                           layout, sink, progress, steps)
                            : render::render_poster(renderer, job.effect, cameras, options, layout, sink, progress,
                                                    steps);
    if (!drawn) {
        return drawn.take_error();
    }
    mark(doing);
    if (auto finished = (*stream)->finish(); !finished) {
        return finished.take_error();
    }
    timing.total_s = seconds_since(start);
    if (job.status && last_status != start) {
        job.status("");
    }
    return PosterFile{thumbnail.image(), timing};
}

} // namespace demo
