#include "demo/warp_report_parts.hpp"

#include <render/lens_pass.hpp>
#include <reference/lens_reference.hpp>

#include <sstream>

namespace demo {

namespace {

// How far the reference itself is from converged: the same at twice the
// supersampling ("-" above 8x).
frustum::Result<std::string> reference_self_check(ReportSession& s, const render::PassContext& ctx,
                                                  const render::LensDraw& draw, const image::Image& reference,
                                                  int supersampling) {
    if (2 * supersampling > 8) {
        return std::string("-");
    }
    if (auto drawn = reference::draw_lens_reference(ctx, *s.frame, draw, 2 * supersampling); !drawn) {
        return drawn.take_error();
    }
    auto finer = s.read();
    if (!finer) {
        return finer.take_error();
    }
    const reference::MirrorError e = picture_error(reference, *finer, kWarpThresholdLsb);
    return fixed(e.mean_abs, 2) + " LSB mean, " + std::to_string(e.max_abs) + " max, " +
           fixed(100.0 * e.fraction_over, 2) + "% of the pixels over " + std::to_string(kWarpThresholdLsb) + " LSB";
}

// The plain frame with the lens disc hidden, median of `runs` (ms).
frustum::Result<double> plain_frame_ms(ReportSession& s, const render::PassContext& ctx, const render::LensDraw& draw,
                                       int runs) {
    return s.median_ms(runs, [&]() -> frustum::Status {
        s.frame->bind();
        render::begin_frame(ctx);
        render::SceneDraw scene{draw.camera};
        scene.skip_instance = draw.skip_instance;
        render::draw_scene(ctx, scene);
        return {};
    });
}

} // namespace

std::variant<WarpReport, Failure> lens_report(const WarpReportRequest& request, ReportSession& s, const Reporter& reporter) {
    const RenderRequest& r = request.render;
    WarpReport report;
    const PngWriter write(r.out_dir, reporter, report.written_paths);
    const int disc = s.scene.lens ? s.scene.lens->instance : -1;
    auto lens = render::lens_on_near_plane(s.cameras->main.pair, s.scene.lens, r.lens_power);
    if (!lens) {
        return runtime(lens.error());
    }
    const render::PassContext ctx = s.pass();
    render::LensDraw draw{s.cameras->main.pair, *lens, 1, disc};

    int levels = 0;
    auto timed_reference = s.timed_read(request.runs, ReportSession::keeping(levels, [&] {
        return reference::draw_lens_reference(ctx, *s.frame, draw, request.supersampling);
    }));
    if (!timed_reference) {
        return runtime(timed_reference.error());
    }
    const double reference_ms = timed_reference->median_ms;
    const image::Image& reference = timed_reference->picture;
    if (auto status = write(reference, "lens-reference.png"); !status) {
        return runtime(status.error());
    }
    auto self_check = reference_self_check(s, ctx, draw, reference, request.supersampling);
    if (!self_check) {
        return runtime(self_check.error());
    }
    auto plain_ms = plain_frame_ms(s, ctx, draw, request.runs);
    if (!plain_ms) {
        return runtime(plain_ms.error());
    }

    MarkdownTable table({"grid", "tiles", "mean error (LSB)", "max error (LSB)",
                         "pixels > " + std::to_string(kWarpThresholdLsb) + " LSB",
                         "frame (ms, median of " + std::to_string(request.runs) + ")"});
    for (int grid : request.grids) {
        reporter.progress("grid " + std::to_string(grid));
        draw.grid = grid;
        auto timed = s.timed_read(request.runs, [&] { return render::draw_lens_frame(ctx, *s.frame, draw); });
        if (!timed) {
            return runtime(timed.error());
        }
        const image::Image& tiled = timed->picture;
        table.row({std::to_string(grid) + " x " + std::to_string(grid), std::to_string(grid * grid),
                   error_cells(picture_error(tiled, reference, kWarpThresholdLsb)), fixed(timed->median_ms, 2)});
        const std::string suffix = std::to_string(grid) + ".png";
        if (auto status = write(tiled, "lens-" + suffix); !status) {
            return runtime(status.error());
        }
        if (auto status = write(diff_picture(tiled, reference), "lens-diff-" + suffix); !status) {
            return runtime(status.error());
        }
    }
    std::ostringstream md;
    md << "Lens: power " << fixed(lens->power, 2) << ", centre (" << fixed(lens->center_m.x * 1e3, 2) << ", "
       << fixed(lens->center_m.y * 1e3, 2) << ") mm, radius " << fixed(lens->radius_m * 1e3, 2)
       << " mm on the near plane; camera '" << s.cameras->main.name << "', " << r.width_px << "x" << r.height_px
       << "; GL: " << s.context->describe().renderer << ".\n"
       << "Reference: " << levels << " nested level(s) at " << request.supersampling << "x, "
       << fixed(reference_ms, 2) << " ms; against itself at " << 2 * request.supersampling << "x: " << *self_check
       << ". Plain frame (lens disc hidden): " << fixed(*plain_ms, 2) << " ms.\n\n"
       << table.text();
    report.markdown = md.str();
    return report;
}

} // namespace demo
