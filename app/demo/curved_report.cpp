#include "demo/curved_report.hpp"

#include "demo/output_dir.hpp"
#include "demo/report_toolkit.hpp"
#include "demo/session.hpp"

#include <frustum/queries.hpp>
#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <image/png.hpp>
#include <plan/camera.hpp>
#include <plan/curved_mirror.hpp>
#include <render/curved_pass.hpp>
#include <reference/curved_reference.hpp>
#include <render/renderer.hpp>
#include <scene/load_gltf.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>

namespace demo {
namespace {

constexpr int kThresholdLsb = 24; // "visibly wrong": as the planar mirror tests
constexpr int kTimedRuns = 5;     // best of these: the machine may be shared

struct Rect {
    int x = 0, y = 0, width = 0, height = 0; // image rows from the top
};

// The mask's bounding box grown by `margin`, clamped to the image.
Rect bounding_box(const std::vector<bool>& mask, int width, int height, int margin) {
    int x0 = width, y0 = height, x1 = -1, y1 = -1;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (mask[static_cast<std::size_t>(y * width + x)]) {
                x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
            }
        }
    }
    if (x1 < 0) {
        return {0, 0, width, height};
    }
    x0 = std::max(0, x0 - margin), y0 = std::max(0, y0 - margin);
    x1 = std::min(width - 1, x1 + margin), y1 = std::min(height - 1, y1 + margin);
    return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

image::Image crop(const image::Image& picture, const Rect& r) {
    image::Image out = image::make_image(r.width, r.height, {0, 0, 0, 255});
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            image::set_pixel(out, x, y, image::pixel_at(picture, r.x + x, r.y + y));
        }
    }
    return out;
}

// The composite with tint 0 paints exactly the cap's visible pixels black
// (nothing else in the showcase is pure black: ambient light).
std::vector<bool> black_pixels(const image::Image& picture) {
    std::vector<bool> out(static_cast<std::size_t>(picture.width * picture.height));
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            const image::Rgba p = image::pixel_at(picture, x, y);
            out[static_cast<std::size_t>(y * picture.width + x)] = p[0] == 0 && p[1] == 0 && p[2] == 0;
        }
    }
    return out;
}

// The red marker's lit colour (tests/gl/render_test_support.hpp).
int count_red(const image::Image& picture, const std::vector<bool>& mask) {
    int red = 0;
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            const image::Rgba p = image::pixel_at(picture, x, y);
            red += mask[static_cast<std::size_t>(y * picture.width + x)] && p[0] >= 100 && p[1] <= 40 && p[2] <= 40;
        }
    }
    return red;
}

struct Summary {
    double min = std::numeric_limits<double>::infinity(), max = -std::numeric_limits<double>::infinity(), sum = 0;
    int count = 0;
    void add(double v) {
        if (std::isfinite(v)) min = std::min(min, v), max = std::max(max, v), sum += v, ++count;
    }
    std::string format(const char* spec) const {
        if (count == 0) return "-";
        char buffer[96];
        std::snprintf(buffer, sizeof buffer, (std::string(spec) + " / " + spec + " / " + spec).c_str(), min,
                      sum / count, max);
        return buffer;
    }
};

} // namespace

std::string curved_report_help() {
    return "frustum-demo curved-report: the curved mirror (paper §4.3) with G x G patches against a\n"
           "per-pixel ray-traced reference; prints a Markdown report on stdout.\n"
           "\n"
           "usage:\n"
           "  frustum-demo curved-report [options]\n"
           "\n"
           "options:\n" +
           options_help(kCurvedReport, false) + "effect options (as in render):\n" +
           options_help(kCurvedReport, true) + "\n" +
           "Writes DIR/curved-<G>.png, DIR/curved-diff-<G>.png (|rendered - reference| x 4 on the\n"
           "mirror) and DIR/curved-reference.png, cropped to the mirror; prints each path on stderr.\n";
}

std::variant<HelpRequest, CurvedReportRequest, Failure> parse_curved_report(const std::vector<std::string>& args) {
    auto parsed = parse_options(kCurvedReport, args);
    if (auto early = failure_or_help<std::variant<HelpRequest, CurvedReportRequest, Failure>>(parsed)) {
        return *early;
    }
    CurvedReportRequest request;
    request.render = std::get<Settings>(parsed);
    request.patch_counts = request.render.patch_counts;
    return request;
}

namespace {

// What every patch count is measured against: the session, the cap, the
// eye, the traced references (curved and flat) and the crop box.
struct CurvedPlan {
    std::unique_ptr<Session> session;
    std::optional<plan::CurvedMirror> mirror;
    glm::vec4 eye{0.0f};
    std::optional<reference::TracedFrame> traced, flat_traced; // the flat one: sagitta 0, the sampling floor
    double trace_ms = 0.0;
    Rect box;
    render::RenderOptions options; // the frame's size, depth and cap; a perfect mirror, as traced
};

// One row of the tables: G x G patches against the reference.
struct CurvedRow {
    int grid = 0;
    glm::ivec2 tile{0};
    double fit_ms = 0.0, frame_ms = 0.0;
    reference::MirrorError error, flat_error;
    reference::RayAngleError angle;
    int red_px = 0;
    Summary iterations, objective, start;
    int failed = 0;
    std::string failures; // "- G = 4, ..." per patch without a frustum
};

struct CurvedMeasures {
    double planar_ms = 0.0;
    std::vector<CurvedRow> rows;
};

std::variant<CurvedPlan, Failure> plan_report(const RenderRequest& r, const Reporter& reporter,
                                              const PngWriter& write_cropped) {
    CurvedPlan plan;
    plan.session = std::make_unique<Session>(); // on the heap: GL objects point to its members
    Session& session = *plan.session;
    // As render opens it: a scene without a mirror gets the floor mirror,
    // the sagitta is fitted to it unless --sagitta is given (and checked).
    if (auto failure = session.open(r, reporter)) {
        return *failure;
    }
    const scene::Scene& scene = session.scene;
    const plan::CurvedMirrorOptions& curved = session.effects.params.curved;
    const plan::Cameras& cameras = *session.cameras;
    auto mirror = plan::CurvedMirror::create(*scene.mirror, curved.shape, curved.sagitta_m);
    if (!mirror) {
        return runtime(mirror.error());
    }
    plan.mirror.emplace(std::move(*mirror));
    plan.eye = frustum::to_point(frustum::key_points(cameras.main.pair).eye, frustum::infinity_tolerance<float>());
    if (plan.eye.w != 1.0f) {
        return runtime("curved-report: the camera must be perspective");
    }
    reporter.progress("tracing the references");
    const auto trace_start = std::chrono::steady_clock::now();
    auto traced = reference::trace_curved_frame(scene, *plan.mirror, cameras.main.pair, r.width_px, r.height_px, {});
    if (!traced) {
        return runtime(traced.error());
    }
    plan.trace_ms = milliseconds_since(trace_start);
    plan.traced.emplace(std::move(*traced));
    // The same footprint flat (sagitta 0): every patch frustum is then exact
    // (the reflected eye), so its error is the sampling floor.
    auto flat_mirror = plan::CurvedMirror::create(*scene.mirror, curved.shape, 0.0);
    if (!flat_mirror) {
        return runtime(flat_mirror.error());
    }
    auto flat_traced =
        reference::trace_curved_frame(scene, *flat_mirror, cameras.main.pair, r.width_px, r.height_px, {});
    if (!flat_traced) {
        return runtime(flat_traced.error());
    }
    plan.flat_traced.emplace(std::move(*flat_traced));
    plan.box = bounding_box(plan.traced->on_mirror, r.width_px, r.height_px, 6);
    if (auto status = write_cropped(crop(plan.traced->picture, plan.box), "curved-reference.png"); !status) {
        return runtime(status.error());
    }
    plan.options.width_px = r.width_px;
    plan.options.height_px = r.height_px;
    plan.options.depth = r.depth;
    plan.options.curved = curved;
    plan.options.mirror_tint = glm::vec3(1.0f);
    return plan;
}

// Best wall time of kTimedRuns frames (time_runs(): after one warm-up),
// including the read-back that waits for the GPU.
frustum::Result<double> best_frame_ms(const Session& s, plan::Effect effect, const render::RenderOptions& o,
                                      image::Image* picture) {
    auto timing = time_runs(kTimedRuns, [&]() -> frustum::Status {
        auto frame = s.renderer->render(effect, *s.cameras, o);
        if (!frame) {
            return frustum::Error{frame.error()};
        }
        if (picture) {
            *picture = std::move(*frame);
        }
        return {};
    });
    if (!timing) {
        return frustum::Error{timing.error()};
    }
    return timing->best_ms;
}

// Rendered vs traced on the pixels both give to the cap.
frustum::Result<reference::MirrorError> compare_cap(const Session& s, const render::RenderOptions& base,
                                                    const image::Image& rendered,
                                                    const reference::TracedFrame& reference,
                                                    std::vector<bool>* mask_out) {
    render::RenderOptions black_options = base;
    black_options.mirror_tint = glm::vec3(0.0f);
    auto black = s.renderer->render(plan::Effect::Curved, *s.cameras, black_options);
    if (!black) {
        return frustum::Error{black.error()};
    }
    std::vector<bool> mask = black_pixels(*black);
    for (std::size_t p = 0; p < mask.size(); ++p) {
        mask[p] = mask[p] && reference.on_mirror[p];
    }
    const auto e = reference::compare_on_mask(rendered, reference.picture, mask, kThresholdLsb);
    if (mask_out) {
        *mask_out = std::move(mask);
    }
    return e;
}

std::variant<CurvedMeasures, Failure> measure_report(const CurvedReportRequest& request, const CurvedPlan& plan,
                                                     const Reporter& reporter, const PngWriter& write_cropped) {
    const RenderRequest& r = request.render;
    const Session& s = *plan.session;
    CurvedMeasures measures;
    auto planar_ms = best_frame_ms(s, plan::Effect::Mirror, plan.options, nullptr);
    if (!planar_ms) {
        return runtime(planar_ms.error());
    }
    measures.planar_ms = *planar_ms;
    for (int grid : request.patch_counts) {
        reporter.progress("G = " + std::to_string(grid));
        CurvedRow row;
        row.grid = grid;
        // The fit alone (what the frame does first), best of kTimedRuns.
        row.fit_ms = std::numeric_limits<double>::infinity();
        std::optional<plan::CurvedPlan> fit;
        for (int run = 0; run < kTimedRuns; ++run) {
            const auto start = std::chrono::steady_clock::now();
            auto planned = plan::plan_curved_mirror(*plan.mirror, glm::dvec3(glm::vec3(plan.eye)),
                                                    s.scene.world_bounds, grid);
            row.fit_ms = std::min(row.fit_ms, milliseconds_since(start));
            if (!planned) {
                return runtime(planned.error());
            }
            if (!*planned) {
                return runtime("curved-report: the camera is behind the mirror");
            }
            fit = std::move(**planned);
        }
        render::RenderOptions o = plan.options;
        o.curved.patches = grid;
        image::Image picture;
        auto frame_ms = best_frame_ms(s, plan::Effect::Curved, o, &picture);
        if (!frame_ms) {
            return runtime(frame_ms.error());
        }
        row.frame_ms = *frame_ms;
        std::vector<bool> mask;
        auto e = compare_cap(s, o, picture, *plan.traced, &mask);
        if (!e) {
            return runtime(e.error());
        }
        row.error = *e;
        render::RenderOptions flat = o;
        flat.curved.sagitta_m = 0.0f;
        auto flat_picture = s.renderer->render(plan::Effect::Curved, *s.cameras, flat);
        if (!flat_picture) {
            return runtime(flat_picture.error());
        }
        auto flat_error = compare_cap(s, flat, *flat_picture, *plan.flat_traced, nullptr);
        if (!flat_error) {
            return runtime(flat_error.error());
        }
        row.flat_error = *flat_error;
        row.angle = reference::lookup_ray_error(*plan.mirror, *fit, s.cameras->main.pair, r.width_px, r.height_px);
        row.tile = render::curved_tile_size(*plan.mirror, s.cameras->main.pair, grid, r.width_px, r.height_px);
        row.red_px = count_red(picture, mask);
        for (const plan::PatchFrustum& patch : fit->patches) {
            if (patch.pair) {
                row.iterations.add(patch.iterations);
                row.objective.add(patch.objective);
                row.start.add(patch.start_objective);
            } else {
                row.failures += "- G = " + std::to_string(grid) + ", " + patch.error + "\n";
            }
        }
        row.failed = fit->failed;
        const std::string stem = "curved-" + std::to_string(grid);
        if (auto status = write_cropped(crop(picture, plan.box), stem + ".png"); !status) {
            return runtime(status.error());
        }
        const image::Image diff = diff_picture(picture, plan.traced->picture, &mask);
        if (auto status = write_cropped(crop(diff, plan.box), "curved-diff-" + std::to_string(grid) + ".png"); !status) {
            return runtime(status.error());
        }
        measures.rows.push_back(std::move(row));
    }
    return measures;
}

std::string format_report(const RenderRequest& r, const CurvedPlan& plan, const CurvedMeasures& measures) {
    const std::string over = "> " + std::to_string(kThresholdLsb) + " LSB";
    MarkdownTable errors({"G", "patches", "tile (px)", "fit (ms)", "frame (ms)", "mean error", "max error", over,
                          "ray angle mean / max (deg)", "flat cap: mean error, " + over, "red marker px"});
    MarkdownTable fits({"G", "iterations min / mean / max", "F min / mean / max",
                        "F at intersect(T0, T1, T2), min / mean / max", "failed"});
    std::string failures;
    for (const CurvedRow& row : measures.rows) {
        errors.row({std::to_string(row.grid), std::to_string(row.grid * row.grid),
                    std::to_string(row.tile.x) + " x " + std::to_string(row.tile.y), fixed(row.fit_ms, 2),
                    fixed(row.frame_ms, 1), fixed(row.error.mean_abs, 2), std::to_string(row.error.max_abs),
                    fixed(100.0 * row.error.fraction_over, 1) + "%",
                    row.angle.pixels > 0 ? fixed(row.angle.mean_deg, 3) + " / " + fixed(row.angle.max_deg, 3) : "-",
                    fixed(row.flat_error.mean_abs, 2) + ", " + fixed(100.0 * row.flat_error.fraction_over, 1) + "%",
                    std::to_string(row.red_px)});
        fits.row({std::to_string(row.grid), row.iterations.format("%.0f"), row.objective.format("%.6f"),
                  row.start.format("%.6f"), std::to_string(row.failed)});
        failures += row.failures;
    }
    const int compared = measures.rows.empty() ? 0 : measures.rows.back().error.pixels;
    std::ostringstream md;
    md << "Curved mirror: " << plan::to_string(plan.options.curved.shape) << " cap, sagitta "
       << fixed(plan.options.curved.sagitta_m, 2) << " m, over the scene's mirror; camera '" << plan.session->cameras->main.name << "', " << r.width_px << "x"
       << r.height_px << "; " << compared << " mirror pixels compared; reference traced in "
       << fixed(plan.trace_ms, 0) << " ms; planar mirror frame (oblique): " << fixed(measures.planar_ms, 1)
       << " ms; GL: " << plan.session->context->describe().renderer << ".\n\n"
       << errors.text() << "\n" << fits.text()
       << (failures.empty() ? "" : "\nPatches without a frustum (clear colour):\n") << failures;
    return md.str();
}

} // namespace

std::variant<CurvedReport, Failure> run_curved_report(const CurvedReportRequest& request, const Reporter& reporter) {
    const RenderRequest& r = request.render;
    if (auto status = prepare_output_dir(r.out_dir); !status) {
        return runtime(status.error());
    }
    CurvedReport report;
    const PngWriter write(r.out_dir, reporter, report.written_paths); // pictures cropped to the mirror
    auto plan = plan_report(r, reporter, write);
    if (auto* failure = std::get_if<Failure>(&plan)) {
        return *failure;
    }
    auto measures = measure_report(request, std::get<CurvedPlan>(plan), reporter, write);
    if (auto* failure = std::get_if<Failure>(&measures)) {
        return *failure;
    }
    report.markdown = format_report(r, std::get<CurvedPlan>(plan), std::get<CurvedMeasures>(measures));
    return report;
}

} // namespace demo
