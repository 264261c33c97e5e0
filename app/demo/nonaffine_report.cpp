#include "demo/warp_report_parts.hpp"

#include <render/non_affine_pass.hpp>
#include <reference/non_affine_reference.hpp>

#include <chrono>
#include <map>
#include <sstream>

namespace demo {

namespace {

// One configuration of the table: the naive eq. 36 first, then culling with
// each subdivision edge.
struct Row {
    std::string label, stem;
    plan::NonAffineOptions options;
};

std::vector<Row> report_rows(const plan::NonAffineOptions& defaults, const std::vector<float>& max_edges_m) {
    std::vector<Row> rows;
    plan::NonAffineOptions naive = defaults;
    naive.cull = false;
    naive.max_edge_m = 0.0f;
    rows.push_back({"naive eq. 36 (no cull, no subdivision)", "nonaffine-naive", naive});
    for (float edge : max_edges_m) {
        plan::NonAffineOptions o = defaults;
        o.max_edge_m = edge;
        const std::string edge_text = edge > 0.0f ? fixed(edge, 2) : std::string("none");
        rows.push_back({"cull, subdivision " + edge_text + (edge > 0.0f ? " m" : ""),
                        "nonaffine-" + (edge > 0.0f ? fixed(edge, 2) + "m" : std::string("cull")), o});
    }
    return rows;
}

// Where the degenerate set cuts the scene: the original triangles culled
// (a vertex within `guard_m` of it), per node.
std::map<std::string, int> culled_by_node_name(const plan::WorldGeometry& geometry,
                                               const frustum::NonAffineFrustum<float>& frustum, float guard_m,
                                               const scene::Scene& scene) {
    std::map<std::string, int> culled;
    for (const plan::WorldPrimitive& p : geometry.primitives) {
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            bool degenerate = false;
            for (std::size_t v = 0; v < 3; ++v) {
                degenerate = degenerate || render::is_degenerate(frustum, p.vertices[p.indices[t + v]].position, guard_m);
            }
            if (degenerate) {
                ++culled[scene.instances[static_cast<std::size_t>(p.instance)].node_name];
            }
        }
    }
    return culled;
}

} // namespace

std::variant<WarpReport, Failure> nonaffine_report(const WarpReportRequest& request, ReportSession& s,
                                                   const Reporter& reporter) {
    const RenderRequest& r = request.render;
    WarpReport report;
    const PngWriter write(r.out_dir, reporter, report.written_paths);
    const render::PassContext ctx = s.pass();
    plan::NonAffineOptions defaults;
    if (request.slit_depth_m > 0.0f) {
        defaults.slit_depth_m = request.slit_depth_m;
    }
    if (request.pivot_depth_m > 0.0f) {
        defaults.pivot_depth_m = request.pivot_depth_m;
    }
    auto frustum = plan::crossed_slits_frustum(s.cameras->main.pair, defaults, s.depth->gpu_range());
    if (!frustum) {
        return runtime(frustum.error());
    }
    const plan::WorldGeometry geometry = plan::WorldGeometry::from_scene(s.scene);

    reporter.progress("ray casting the reference");
    const auto cast_start = std::chrono::steady_clock::now();
    const image::Image reference =
        reference::ray_cast_non_affine(geometry, *frustum, render::Lighting{}, render::kClearColor, r.width_px, r.height_px);
    const double cast_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cast_start).count();
    if (auto status = write(reference, "nonaffine-reference.png"); !status) {
        return runtime(status.error());
    }

    const std::vector<Row> rows = report_rows(defaults, request.max_edges_m);
    MarkdownTable table({"configuration", "triangles", "culled", "mean error (LSB)", "max error (LSB)",
                         "pixels > " + std::to_string(kWarpThresholdLsb) + " LSB",
                         "frame (ms, median of " + std::to_string(request.runs) + ")"});
    image::Image last;
    for (const Row& row : rows) {
        reporter.progress(row.label);
        render::NonAffineStats stats;
        auto timed = s.timed_read(request.runs, ReportSession::keeping(stats, [&] {
            return render::draw_non_affine_frame(ctx, *s.frame, geometry, *frustum, row.options);
        }));
        if (!timed) {
            return runtime(timed.error());
        }
        const image::Image& picture = timed->picture;
        table.row({row.label, std::to_string(stats.triangles), std::to_string(stats.culled),
                   error_cells(picture_error(picture, reference, kWarpThresholdLsb)), fixed(timed->median_ms, 2)});
        if (auto status = write(picture, row.stem + ".png"); !status) {
            return runtime(status.error());
        }
        if (row.stem == "nonaffine-cull") {
            if (auto status = write(diff_picture(picture, reference), "nonaffine-diff-cull.png"); !status) {
                return runtime(status.error());
            }
        }
        last = std::move(timed->picture);
    }
    if (auto status = write(diff_picture(last, reference), "nonaffine-diff.png"); !status) {
        return runtime(status.error());
    }
    const std::map<std::string, int> culled_by_node = culled_by_node_name(geometry, *frustum, defaults.guard_m, s.scene);
    std::ostringstream md;
    md << "Non-affine frustum: crossed slits, slit " << fixed(defaults.slit_depth_m, 2) << " m and pivot "
       << fixed(defaults.pivot_depth_m, 2) << " m in front of the eye of camera '" << s.cameras->main.name
       << "'; guard " << fixed(defaults.guard_m, 3) << " m; " << r.width_px << "x" << r.height_px
       << "; GL: " << s.context->describe().renderer << ".\nReference: CPU ray cast, " << fixed(cast_ms, 0)
       << " ms. Original triangles culled (a vertex within the guard of the degenerate set), by node:";
    for (const auto& [node, count] : culled_by_node) {
        md << " " << node << " " << count << ";";
    }
    md << "\n\n" << table.text();
    report.markdown = md.str();
    return report;
}

} // namespace demo
