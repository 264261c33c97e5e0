#include "demo/curved_report.hpp"

#include "demo/output_dir.hpp"
#include "demo/run_render.hpp"

#include <frustum/queries.hpp>
#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <image/png.hpp>
#include <render/camera.hpp>
#include <render/curved_mirror.hpp>
#include <render/curved_pass.hpp>
#include <render/curved_reference.hpp>
#include <render/renderer.hpp>
#include <scene/load_gltf.hpp>

#include <algorithm>
#include <charconv>
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
constexpr int kDiffGain = 4;

Failure usage(std::string message) { return {ExitStatus::UsageError, std::move(message)}; }
Failure runtime(std::string message) { return {ExitStatus::RuntimeFailure, std::move(message)}; }

// "1,2,4" -> {1, 2, 4}.
std::optional<std::vector<int>> parse_counts(const std::string& text) {
    std::vector<int> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const char* first = text.data() + start;
        const char* last = text.data() + comma;
        int value = 0;
        const auto [end, error] = std::from_chars(first, last, value);
        if (first == last || error != std::errc() || end != last || value < 1 || value > render::kMaxCurvedPatches) {
            return std::nullopt;
        }
        out.push_back(value);
        start = comma + 1;
    }
    return out;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

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

// Inside the mask |a - b| x gain; outside, a at a quarter of its brightness.
image::Image masked_diff(const image::Image& a, const image::Image& b, const std::vector<bool>& mask) {
    image::Image out = image::make_image(a.width, a.height, {0, 0, 0, 255});
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const image::Rgba p = image::pixel_at(a, x, y), q = image::pixel_at(b, x, y);
            image::Rgba o{0, 0, 0, 255};
            for (std::size_t c = 0; c < 3; ++c) {
                const int value = mask[static_cast<std::size_t>(y * a.width + x)]
                                      ? std::min(255, kDiffGain * std::abs(int{p[c]} - int{q[c]}))
                                      : p[c] / 4;
                o[c] = static_cast<std::uint8_t>(value);
            }
            image::set_pixel(out, x, y, o);
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

std::string fixed(double value, int decimals) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

} // namespace

std::string curved_report_help() {
    return "frustum-demo curved-report: the curved mirror (paper §4.3) with G x G patches against a\n"
           "per-pixel ray-traced reference; prints a Markdown report on stdout.\n"
           "\n"
           "usage:\n"
           "  frustum-demo curved-report [options]\n"
           "\n"
           "options:\n"
           "  --patches LIST      patch grids G to compare, comma-separated, 1..64 (default 1,2,4,8,16)\n"
           "  --sagitta M, --cap C, --scene FILE, --camera NAME|INDEX, --size WxH, --backend B,\n"
           "  --depth D, --out DIR as for frustum-demo render (see frustum-demo --help)\n"
           "\n"
           "Writes DIR/curved-<G>.png, DIR/curved-diff-<G>.png (|rendered - reference| x 4 on the\n"
           "mirror) and DIR/curved-reference.png, cropped to the mirror; prints each path on stderr.\n";
}

std::variant<HelpRequest, CurvedReportRequest, Failure> parse_curved_report(const std::vector<std::string>& args) {
    CurvedReportRequest request;
    request.patch_counts = {1, 2, 4, 8, 16};
    std::vector<std::string> forwarded{"render"};
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& name = args[i];
        if (name == "--help" || name == "-h") {
            return HelpRequest{};
        }
        if (name == "--effect" || name == "--tiles" || name == "--mirror") {
            return usage(name + " does not apply to curved-report (see frustum-demo curved-report --help)");
        }
        if (name == "--patches") {
            if (i + 1 >= args.size()) {
                return usage("--patches needs a value (see frustum-demo curved-report --help)");
            }
            const auto counts = parse_counts(args[++i]);
            if (!counts) {
                return usage("--patches must be a comma-separated list of whole numbers in 1.." +
                             std::to_string(render::kMaxCurvedPatches) + ", got '" + args[i] + "'");
            }
            request.patch_counts = *counts;
            continue;
        }
        forwarded.push_back(name);
    }
    auto parsed = parse_command_line(forwarded);
    if (auto* failure = std::get_if<Failure>(&parsed)) {
        return *failure;
    }
    if (std::holds_alternative<HelpRequest>(parsed)) {
        return HelpRequest{};
    }
    request.render = std::get<RenderRequest>(parsed);
    return request;
}

std::variant<CurvedReport, Failure> run_curved_report(const CurvedReportRequest& request, const Reporter& reporter) {
    const RenderRequest& r = request.render;
    if (auto status = prepare_output_dir(r.out_dir); !status) {
        return runtime(status.error());
    }
    auto scene = scene::load_gltf(r.scene_path);
    if (!scene) {
        return runtime(scene.error());
    }
    if (!scene->mirror) {
        return runtime("curved-report: the scene has no mirror (a node named 'mirror', assets/README.md)");
    }
    auto camera_index = render::find_camera(*scene, r.camera);
    if (!camera_index) {
        return usage(camera_index.error());
    }
    auto cameras = render::make_cameras(*scene, *camera_index, r.width_px, r.height_px);
    if (!cameras) {
        return runtime(cameras.error());
    }
    auto mirror = render::CurvedMirror::create(*scene->mirror, r.curved.shape, r.curved.sagitta_m);
    if (!mirror) {
        return runtime(mirror.error());
    }
    const auto eye = frustum::eye_point(cameras->main.pair);
    if (!eye) {
        return runtime("curved-report: the camera must be perspective");
    }
    auto context = make_context(r, reporter);
    if (!context) {
        return runtime(context.error());
    }
    auto fn = gl::Functions::load(**context);
    if (!fn) {
        return runtime(fn.error());
    }
    auto renderer = render::Renderer::create(**context, *fn, *scene);
    if (!renderer) {
        return runtime(renderer.error());
    }

    reporter.progress("tracing the references");
    const auto trace_start = std::chrono::steady_clock::now();
    auto traced = render::trace_curved_frame(*scene, *mirror, cameras->main.pair, r.width_px, r.height_px, {});
    if (!traced) {
        return runtime(traced.error());
    }
    const double trace_ms = milliseconds_since(trace_start);
    // The same footprint flat (sagitta 0): every patch frustum is then exact
    // (the reflected eye), so its error is the sampling floor.
    auto flat_mirror = render::CurvedMirror::create(*scene->mirror, r.curved.shape, 0.0);
    if (!flat_mirror) {
        return runtime(flat_mirror.error());
    }
    auto flat_traced =
        render::trace_curved_frame(*scene, *flat_mirror, cameras->main.pair, r.width_px, r.height_px, {});
    if (!flat_traced) {
        return runtime(flat_traced.error());
    }
    const Rect box = bounding_box(traced->on_mirror, r.width_px, r.height_px, 6);

    CurvedReport report;
    const auto write = [&](const image::Image& picture, const std::string& name) -> frustum::Status {
        const std::string path = r.out_dir + "/" + name;
        if (auto status = image::write_png(crop(picture, box), path); !status) {
            return status;
        }
        report.written_paths.push_back(path);
        reporter.progress(path);
        return {};
    };
    if (auto status = write(traced->picture, "curved-reference.png"); !status) {
        return runtime(status.error());
    }

    render::RenderOptions options;
    options.width_px = r.width_px;
    options.height_px = r.height_px;
    options.depth = r.depth;
    options.curved = r.curved;
    options.mirror_tint = glm::vec3(1.0f); // a perfect mirror, as traced
    // Best wall time of kTimedRuns frames (after one warm-up), including the
    // read-back that waits for the GPU.
    const auto timed = [&](render::Effect effect, const render::RenderOptions& o,
                           image::Image* picture) -> frustum::Result<double> {
        std::vector<double> times;
        for (int run = 0; run <= kTimedRuns; ++run) {
            const auto start = std::chrono::steady_clock::now();
            auto frame = renderer->render(effect, *cameras, o);
            if (!frame) {
                return frame.take_error();
            }
            if (run > 0) times.push_back(milliseconds_since(start));
            if (picture) *picture = std::move(*frame);
        }
        return *std::min_element(times.begin(), times.end());
    };
    auto planar_ms = timed(render::Effect::Mirror, options, nullptr);
    if (!planar_ms) {
        return runtime(planar_ms.error());
    }

    std::ostringstream errors, fits;
    errors << "| G | patches | tile (px) | fit (ms) | frame (ms) | mean error | max error | > " << kThresholdLsb
           << " LSB | ray angle mean / max (deg) | flat cap: mean error, > " << kThresholdLsb
           << " LSB | red marker px |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    fits << "| G | iterations min / mean / max | F min / mean / max | F at intersect(T0, T1, T2), min / mean / max "
            "| failed |\n|---|---|---|---|---|\n";
    std::string failures;
    int compared = 0;
    for (int grid : request.patch_counts) {
        reporter.progress("G = " + std::to_string(grid));
        // The fit alone (what the frame does first), best of kTimedRuns.
        double fit_ms = std::numeric_limits<double>::infinity();
        std::optional<render::CurvedPlan> plan;
        for (int run = 0; run < kTimedRuns; ++run) {
            const auto start = std::chrono::steady_clock::now();
            auto planned = render::plan_curved_mirror(*mirror, glm::dvec3(*eye), scene->world_bounds, grid);
            fit_ms = std::min(fit_ms, milliseconds_since(start));
            if (!planned) {
                return runtime(planned.error());
            }
            if (!*planned) {
                return runtime("curved-report: the camera is behind the mirror");
            }
            plan = std::move(**planned);
        }
        render::RenderOptions o = options;
        o.curved.patches = grid;
        image::Image picture;
        auto frame_ms = timed(render::Effect::Curved, o, &picture);
        if (!frame_ms) {
            return runtime(frame_ms.error());
        }
        // Rendered vs traced on the pixels both give to the cap.
        const auto compare = [&](const render::RenderOptions& base, const image::Image& rendered,
                                 const render::TracedFrame& reference,
                                 std::vector<bool>* mask_out) -> frustum::Result<render::MirrorError> {
            render::RenderOptions black_options = base;
            black_options.mirror_tint = glm::vec3(0.0f);
            auto black = renderer->render(render::Effect::Curved, *cameras, black_options);
            if (!black) {
                return black.take_error();
            }
            std::vector<bool> mask = black_pixels(*black);
            for (std::size_t p = 0; p < mask.size(); ++p) {
                mask[p] = mask[p] && reference.on_mirror[p];
            }
            const auto e = render::compare_on_mask(rendered, reference.picture, mask, kThresholdLsb);
            if (mask_out) *mask_out = std::move(mask);
            return e;
        };
        std::vector<bool> mask;
        auto e = compare(o, picture, *traced, &mask);
        if (!e) {
            return runtime(e.error());
        }
        compared = e->pixels;
        render::RenderOptions flat = o;
        flat.curved.sagitta_m = 0.0f;
        auto flat_picture = renderer->render(render::Effect::Curved, *cameras, flat);
        if (!flat_picture) {
            return runtime(flat_picture.error());
        }
        auto flat_error = compare(flat, *flat_picture, *flat_traced, nullptr);
        if (!flat_error) {
            return runtime(flat_error.error());
        }
        const auto angle = render::lookup_ray_error(*mirror, *plan, cameras->main.pair, r.width_px, r.height_px);
        const glm::ivec2 tile = render::curved_tile_size(*mirror, cameras->main.pair, grid, r.width_px, r.height_px);
        errors << "| " << grid << " | " << grid * grid << " | " << tile.x << " x " << tile.y << " | "
               << fixed(fit_ms, 2) << " | " << fixed(*frame_ms, 1) << " | " << fixed(e->mean_abs, 2) << " | "
               << e->max_abs << " | " << fixed(100.0 * e->fraction_over, 1) << "% | "
               << (angle.pixels > 0 ? fixed(angle.mean_deg, 3) + " / " + fixed(angle.max_deg, 3) : "-") << " | " << fixed(flat_error->mean_abs, 2) << ", "
               << fixed(100.0 * flat_error->fraction_over, 1) << "% | " << count_red(picture, mask) << " |\n";
        Summary iterations, objective, start;
        for (const render::PatchFrustum& patch : plan->patches) {
            if (patch.pair) {
                iterations.add(patch.iterations);
                objective.add(patch.objective);
                start.add(patch.start_objective);
            } else {
                failures += "- G = " + std::to_string(grid) + ", " + patch.error + "\n";
            }
        }
        fits << "| " << grid << " | " << iterations.format("%.0f") << " | " << objective.format("%.6f") << " | "
             << start.format("%.6f") << " | " << plan->failed << " |\n";
        const std::string stem = "curved-" + std::to_string(grid);
        if (auto status = write(picture, stem + ".png"); !status) {
            return runtime(status.error());
        }
        if (auto status = write(masked_diff(picture, traced->picture, mask), "curved-diff-" + std::to_string(grid) + ".png");
            !status) {
            return runtime(status.error());
        }
    }
    std::ostringstream md;
    md << "Curved mirror: " << render::to_string(r.curved.shape) << " cap, sagitta " << fixed(r.curved.sagitta_m, 2)
       << " m, over the scene's mirror; camera '" << cameras->main.name << "', " << r.width_px << "x" << r.height_px
       << "; " << compared << " mirror pixels compared; reference traced in " << fixed(trace_ms, 0)
       << " ms; planar mirror frame (oblique): " << fixed(*planar_ms, 1) << " ms; GL: "
       << (*context)->describe().renderer << ".\n\n"
       << errors.str() << "\n" << fits.str() << (failures.empty() ? "" : "\nPatches without a frustum (clear colour):\n")
       << failures;
    report.markdown = md.str();
    return report;
}

} // namespace demo
