#include "demo/warp_reports.hpp"

#include "demo/output_dir.hpp"
#include "demo/warp_report_parts.hpp"

#include <algorithm>
#include <memory>
#include <utility>

namespace demo {
namespace {

std::variant<std::unique_ptr<ReportSession>, Failure> open_session(const RenderRequest& r, const Reporter& reporter) {
    auto s = std::make_unique<ReportSession>();
    if (auto failure = s->open(r, reporter)) {
        return *failure;
    }
    auto depth = render::DepthPolicy::apply(*s->fn, *s->context, r.depth);
    if (!depth) {
        return runtime(depth.error());
    }
    s->depth.emplace(*depth);
    auto frame = gl::OffscreenTarget::create(*s->fn, {r.width_px, r.height_px});
    if (!frame) {
        return runtime(frame.error());
    }
    s->frame.emplace(std::move(*frame));
    return s;
}

} // namespace

std::string warp_report_help(const std::string& command) {
    if (command == "lens-report") {
        return "frustum-demo lens-report: the tiled lens (paper §5.4) for several grids against the per-pixel\n"
               "remap reference (eq. 34 in GLSL); prints a Markdown table on stdout.\n"
               "\n"
               "usage:\n"
               "  frustum-demo lens-report [options]\n"
               "\n"
               "options:\n" +
               options_help(kLensReport, false) + "effect options (as in render):\n" +
               options_help(kLensReport, true) +
               "\n"
               "Writes DIR/lens-<N>.png, DIR/lens-diff-<N>.png (|tiled - reference| x 4) and\n"
               "DIR/lens-reference.png; prints each path on stderr.\n";
    }
    return "frustum-demo nonaffine-report: the non-affine effect (paper §6, eq. 36) naive, culled, and culled +\n"
           "subdivided, against a CPU ray cast; prints a Markdown table on stdout.\n"
           "\n"
           "usage:\n"
           "  frustum-demo nonaffine-report [options]\n"
           "\n"
           "options:\n" +
           options_help(kNonAffineReport, false) +
           "\n"
           "Writes DIR/nonaffine-naive.png, DIR/nonaffine-cull.png, DIR/nonaffine-<edge>m.png,\n"
           "DIR/nonaffine-reference.png, DIR/nonaffine-diff-cull.png (culled, not subdivided, vs the\n"
           "reference, x 4) and DIR/nonaffine-diff.png (the last row vs the reference, x 4).\n";
}

std::variant<HelpRequest, WarpReportRequest, Failure> parse_warp_report(const std::vector<std::string>& args) {
    WarpReportRequest request;
    request.kind = !args.empty() && args[0] == "lens-report" ? WarpReportRequest::Kind::Lens
                                                             : WarpReportRequest::Kind::NonAffine;
    auto parsed = parse_options(request.kind == WarpReportRequest::Kind::Lens ? kLensReport : kNonAffineReport, args);
    if (auto early = failure_or_help<std::variant<HelpRequest, WarpReportRequest, Failure>>(parsed)) {
        return *early;
    }
    request.render = std::get<Settings>(parsed);
    const Settings& s = request.render;
    request.grids = s.grids;
    request.max_edges_m = s.max_edges_m;
    request.slit_depth_m = s.fit.slit_m.value_or(0.0f);
    request.pivot_depth_m = s.fit.pivot_m.value_or(0.0f);
    request.supersampling = s.supersampling;
    request.runs = s.runs;
    const int smaller_side = std::min(s.width_px, s.height_px);
    for (int grid : request.grids) {
        if (request.kind == WarpReportRequest::Kind::Lens && grid > smaller_side) {
            return Failure{ExitStatus::UsageError,
                           "--grids " + std::to_string(grid) + " needs at least one pixel per tile, but the image is " +
                               std::to_string(s.width_px) + "x" + std::to_string(s.height_px)};
        }
    }
    return request;
}

std::variant<WarpReport, Failure> run_warp_report(const WarpReportRequest& request, const Reporter& reporter) {
    if (auto status = prepare_output_dir(request.render.out_dir); !status) {
        return runtime(status.error());
    }
    auto opened = open_session(request.render, reporter);
    if (auto* failure = std::get_if<Failure>(&opened)) {
        return *failure;
    }
    ReportSession& session = *std::get<std::unique_ptr<ReportSession>>(opened);
    return request.kind == WarpReportRequest::Kind::Lens ? lens_report(request, session, reporter)
                                                         : nonaffine_report(request, session, reporter);
}

} // namespace demo