#include "demo/warp_reports.hpp"

#include "demo/output_dir.hpp"

#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <image/png.hpp>
#include <render/camera.hpp>
#include <render/lens_pass.hpp>
#include <render/lens_reference.hpp>
#include <render/non_affine_pass.hpp>
#include <render/non_affine_reference.hpp>
#include <render/renderer.hpp>
#include <render/scene_pass.hpp>
#include <scene/load_gltf.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

namespace demo {
namespace {

constexpr int kThresholdLsb = 8; // "visibly different" per RGB channel
constexpr int kDiffGain = 4;

Failure usage(std::string message) { return {ExitStatus::UsageError, std::move(message)}; }
Failure runtime(std::string message) { return {ExitStatus::RuntimeFailure, std::move(message)}; }

// "a,b,c" -> values, each accepted by `accept`.
template <class T>
std::optional<std::vector<T>> parse_list(const std::string& text, const std::function<bool(T)>& accept) {
    std::vector<T> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const char* first = text.data() + start;
        const char* last = text.data() + comma;
        T value{};
        const auto [end, error] = std::from_chars(first, last, value);
        if (first == last || error != std::errc() || end != last || !accept(value)) {
            return std::nullopt;
        }
        out.push_back(value);
        start = comma + 1;
    }
    return out;
}

std::string fixed(double value, int decimals) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

// Per-pixel difference over the RGB channels.
struct ImageError {
    double mean_lsb = 0.0; // mean |a - b| over every RGB channel of every pixel
    int max_lsb = 0;
    double fraction_over = 0.0; // pixels with some channel differing by more than kThresholdLsb
};

ImageError image_error(const image::Image& a, const image::Image& b) {
    ImageError e;
    long long sum = 0;
    int over = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const image::Rgba p = image::pixel_at(a, x, y), q = image::pixel_at(b, x, y);
            int worst = 0;
            for (std::size_t c = 0; c < 3; ++c) {
                const int d = std::abs(int{p[c]} - int{q[c]});
                sum += d;
                worst = std::max(worst, d);
            }
            e.max_lsb = std::max(e.max_lsb, worst);
            over += worst > kThresholdLsb;
        }
    }
    const double pixels = static_cast<double>(a.width) * a.height;
    e.mean_lsb = static_cast<double>(sum) / (3.0 * pixels);
    e.fraction_over = over / pixels;
    return e;
}

// |a - b| x kDiffGain per RGB channel.
image::Image diff_picture(const image::Image& a, const image::Image& b) {
    image::Image out = image::make_image(a.width, a.height, {0, 0, 0, 255});
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const image::Rgba p = image::pixel_at(a, x, y), q = image::pixel_at(b, x, y);
            image::Rgba o{0, 0, 0, 255};
            for (std::size_t c = 0; c < 3; ++c) {
                o[c] = static_cast<std::uint8_t>(std::min(255, kDiffGain * std::abs(int{p[c]} - int{q[c]})));
            }
            image::set_pixel(out, x, y, o);
        }
    }
    return out;
}

std::string error_cells(const ImageError& e) {
    return fixed(e.mean_lsb, 2) + " | " + std::to_string(e.max_lsb) + " | " + fixed(100.0 * e.fraction_over, 2) +
           "%";
}

// Everything a report draws with: scene, cameras, context, renderer, one
// target of the frame's size and a pass context on it.
// Members die in reverse: GL objects, then the table they point to, then the context.
struct Session {
    scene::Scene scene;
    std::optional<render::Cameras> cameras;
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<gl::Functions> fn; // stable address: gl objects point to it
    std::optional<render::Renderer> renderer;
    std::optional<render::DepthPolicy> depth;
    std::optional<gl::OffscreenTarget> frame;

    render::PassContext pass() const { return renderer->pass_context(*depth, render::Lighting{}); }

    frustum::Result<image::Image> read() const { return frame->read_rgba8(); }

    // Median wall time (ms) of `runs` draws, each ended by glFinish, after one warm-up.
    frustum::Result<double> median_ms(int runs, const std::function<frustum::Status()>& draw) const {
        std::vector<double> times;
        for (int run = 0; run <= runs; ++run) {
            const auto start = std::chrono::steady_clock::now();
            if (auto status = draw(); !status) {
                return status.take_error();
            }
            fn->Finish();
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            if (run > 0) {
                times.push_back(ms);
            }
        }
        std::sort(times.begin(), times.end());
        return times[times.size() / 2];
    }
};

frustum::Result<std::unique_ptr<Session>> open_session(const RenderRequest& r, const Reporter& reporter) {
    auto s = std::make_unique<Session>();
    auto scene = scene::load_gltf(r.scene_path);
    if (!scene) {
        return scene.take_error();
    }
    s->scene = std::move(*scene);
    auto camera_index = render::find_camera(s->scene, r.camera);
    if (!camera_index) {
        return camera_index.take_error();
    }
    auto cameras = render::make_cameras(s->scene, *camera_index, r.width_px, r.height_px);
    if (!cameras) {
        return cameras.take_error();
    }
    s->cameras.emplace(std::move(*cameras));
    auto context = r.backend ? gl::create_offscreen_context(*r.backend, {})
                             : gl::create_offscreen_context_with_fallback({});
    if (!context) {
        return context.take_error();
    }
    s->context = std::move(*context);
    reporter.note("context: " + gl::summary(s->context->describe()));
    auto fn = gl::Functions::load(*s->context);
    if (!fn) {
        return fn.take_error();
    }
    s->fn = std::make_unique<gl::Functions>(*fn);
    auto renderer = render::Renderer::create(*s->context, *s->fn, s->scene);
    if (!renderer) {
        return renderer.take_error();
    }
    s->renderer.emplace(std::move(*renderer));
    auto depth = render::DepthPolicy::apply(*s->fn, *s->context, r.depth);
    if (!depth) {
        return depth.take_error();
    }
    s->depth.emplace(*depth);
    auto frame = gl::OffscreenTarget::create(*s->fn, {r.width_px, r.height_px});
    if (!frame) {
        return frame.take_error();
    }
    s->frame.emplace(std::move(*frame));
    return s;
}

class Writer {
public:
    Writer(const std::string& dir, const Reporter& reporter, WarpReport& report)
        : dir_(dir), reporter_(reporter), report_(report) {}
    frustum::Status operator()(const image::Image& picture, const std::string& name) {
        const std::string path = dir_ + "/" + name;
        if (auto status = image::write_png(picture, path); !status) {
            return status;
        }
        report_.written_paths.push_back(path);
        reporter_.progress(path);
        return {};
    }

private:
    const std::string& dir_;
    const Reporter& reporter_;
    WarpReport& report_;
};

std::variant<WarpReport, Failure> lens_report(const WarpReportRequest& request, Session& s, const Reporter& reporter) {
    const RenderRequest& r = request.render;
    WarpReport report;
    Writer write(r.out_dir, reporter, report);
    const int disc = s.scene.lens ? s.scene.lens->instance : -1;
    auto lens = render::lens_on_near_plane(s.cameras->main.pair, s.scene.lens, r.lens_power);
    if (!lens) {
        return runtime(lens.error());
    }
    const render::PassContext ctx = s.pass();
    render::LensDraw draw{s.cameras->main.pair, *lens, 1, disc};

    int levels = 0;
    auto reference_ms = s.median_ms(request.runs, [&]() -> frustum::Status {
        auto drawn = render::draw_lens_reference(ctx, *s.frame, draw, request.supersampling);
        if (!drawn) {
            return drawn.take_error();
        }
        levels = *drawn;
        return {};
    });
    if (!reference_ms) {
        return runtime(reference_ms.error());
    }
    auto reference = s.read();
    if (!reference) {
        return runtime(reference.error());
    }
    if (auto status = write(*reference, "lens-reference.png"); !status) {
        return runtime(status.error());
    }
    // How far the reference itself is from converged: the same at twice the supersampling.
    std::string self_check = "-";
    if (2 * request.supersampling <= 8) {
        if (auto drawn = render::draw_lens_reference(ctx, *s.frame, draw, 2 * request.supersampling); !drawn) {
            return runtime(drawn.error());
        }
        auto finer = s.read();
        if (!finer) {
            return runtime(finer.error());
        }
        const ImageError e = image_error(*reference, *finer);
        self_check = fixed(e.mean_lsb, 2) + " LSB mean, " + std::to_string(e.max_lsb) + " max, " +
                     fixed(100.0 * e.fraction_over, 2) + "% of the pixels over " + std::to_string(kThresholdLsb) +
                     " LSB";
    }
    auto plain_ms = s.median_ms(request.runs, [&]() -> frustum::Status {
        s.frame->bind();
        render::begin_frame(ctx);
        render::SceneDraw scene{s.cameras->main.pair};
        scene.skip_instance = disc;
        render::draw_scene(ctx, scene);
        return {};
    });
    if (!plain_ms) {
        return runtime(plain_ms.error());
    }

    std::ostringstream table;
    table << "| grid | tiles | mean error (LSB) | max error (LSB) | pixels > " << kThresholdLsb
          << " LSB | frame (ms, median of " << request.runs << ") |\n|---|---|---|---|---|---|\n";
    for (int grid : request.grids) {
        reporter.progress("grid " + std::to_string(grid));
        draw.grid = grid;
        auto ms = s.median_ms(request.runs, [&] { return render::draw_lens_frame(ctx, *s.frame, draw); });
        if (!ms) {
            return runtime(ms.error());
        }
        auto tiled = s.read();
        if (!tiled) {
            return runtime(tiled.error());
        }
        table << "| " << grid << " x " << grid << " | " << grid * grid << " | " << error_cells(image_error(*tiled, *reference))
              << " | " << fixed(*ms, 2) << " |\n";
        const std::string suffix = std::to_string(grid) + ".png";
        if (auto status = write(*tiled, "lens-" + suffix); !status) {
            return runtime(status.error());
        }
        if (auto status = write(diff_picture(*tiled, *reference), "lens-diff-" + suffix); !status) {
            return runtime(status.error());
        }
    }
    std::ostringstream md;
    md << "Lens: power " << fixed(lens->power, 2) << ", centre (" << fixed(lens->center_m.x * 1e3, 2) << ", "
       << fixed(lens->center_m.y * 1e3, 2) << ") mm, radius " << fixed(lens->radius_m * 1e3, 2)
       << " mm on the near plane; camera '" << s.cameras->main.name << "', " << r.width_px << "x" << r.height_px
       << "; GL: " << s.context->describe().renderer << ".\n"
       << "Reference: " << levels << " nested level(s) at " << request.supersampling << "x, "
       << fixed(*reference_ms, 2) << " ms; against itself at " << 2 * request.supersampling << "x: " << self_check
       << ". Plain frame (lens disc hidden): " << fixed(*plain_ms, 2) << " ms.\n\n"
       << table.str();
    report.markdown = md.str();
    return report;
}

std::variant<WarpReport, Failure> nonaffine_report(const WarpReportRequest& request, Session& s,
                                                   const Reporter& reporter) {
    const RenderRequest& r = request.render;
    WarpReport report;
    Writer write(r.out_dir, reporter, report);
    const render::PassContext ctx = s.pass();
    render::NonAffineOptions defaults;
    if (request.slit_depth_m > 0.0f) {
        defaults.slit_depth_m = request.slit_depth_m;
    }
    if (request.pivot_depth_m > 0.0f) {
        defaults.pivot_depth_m = request.pivot_depth_m;
    }
    auto frustum = render::crossed_slits_frustum(s.cameras->main.pair, defaults, s.depth->gpu_range());
    if (!frustum) {
        return runtime(frustum.error());
    }
    const render::WorldGeometry geometry = render::WorldGeometry::from_scene(s.scene);

    reporter.progress("ray casting the reference");
    const auto cast_start = std::chrono::steady_clock::now();
    const image::Image reference =
        render::ray_cast_non_affine(geometry, *frustum, render::Lighting{}, render::kClearColor, r.width_px, r.height_px);
    const double cast_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cast_start).count();
    if (auto status = write(reference, "nonaffine-reference.png"); !status) {
        return runtime(status.error());
    }

    struct Row {
        std::string label, stem;
        render::NonAffineOptions options;
    };
    std::vector<Row> rows;
    render::NonAffineOptions naive = defaults;
    naive.cull = false;
    naive.max_edge_m = 0.0f;
    rows.push_back({"naive eq. 36 (no cull, no subdivision)", "nonaffine-naive", naive});
    for (float edge : request.max_edges_m) {
        render::NonAffineOptions o = defaults;
        o.max_edge_m = edge;
        const std::string edge_text = edge > 0.0f ? fixed(edge, 2) : std::string("none");
        rows.push_back({"cull, subdivision " + edge_text + (edge > 0.0f ? " m" : ""),
                        "nonaffine-" + (edge > 0.0f ? fixed(edge, 2) + "m" : std::string("cull")), o});
    }
    std::ostringstream table;
    table << "| configuration | triangles | culled | mean error (LSB) | max error (LSB) | pixels > " << kThresholdLsb
          << " LSB | frame (ms, median of " << request.runs << ") |\n|---|---|---|---|---|---|---|\n";
    image::Image last;
    std::map<std::string, int> culled_by_node;
    for (const Row& row : rows) {
        reporter.progress(row.label);
        render::NonAffineStats stats;
        auto ms = s.median_ms(request.runs, [&]() -> frustum::Status {
            auto drawn = render::draw_non_affine_frame(ctx, *s.frame, geometry, *frustum, row.options);
            if (!drawn) {
                return drawn.take_error();
            }
            stats = *drawn;
            return {};
        });
        if (!ms) {
            return runtime(ms.error());
        }
        auto picture = s.read();
        if (!picture) {
            return runtime(picture.error());
        }
        table << "| " << row.label << " | " << stats.triangles << " | " << stats.culled << " | "
              << error_cells(image_error(*picture, reference)) << " | " << fixed(*ms, 2) << " |\n";
        if (auto status = write(*picture, row.stem + ".png"); !status) {
            return runtime(status.error());
        }
        if (row.stem == "nonaffine-cull") {
            if (auto status = write(diff_picture(*picture, reference), "nonaffine-diff-cull.png"); !status) {
                return runtime(status.error());
            }
        }
        last = std::move(*picture);
    }
    if (auto status = write(diff_picture(last, reference), "nonaffine-diff.png"); !status) {
        return runtime(status.error());
    }
    // Where the degenerate set cuts the scene: the original triangles culled, per node.
    for (const render::WorldPrimitive& p : geometry.primitives) {
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            bool degenerate = false;
            for (std::size_t v = 0; v < 3; ++v) {
                degenerate = degenerate || render::is_degenerate(*frustum, p.vertices[p.indices[t + v]].position,
                                                                 defaults.guard_m);
            }
            if (degenerate) {
                ++culled_by_node[s.scene.instances[static_cast<std::size_t>(p.instance)].node_name];
            }
        }
    }
    std::ostringstream md;
    md << "Non-affine frustum: crossed slits, slit " << fixed(defaults.slit_depth_m, 2) << " m and pivot "
       << fixed(defaults.pivot_depth_m, 2) << " m in front of the eye of camera '" << s.cameras->main.name
       << "'; guard " << fixed(defaults.guard_m, 3) << " m; " << r.width_px << "x" << r.height_px
       << "; GL: " << s.context->describe().renderer << ".\nReference: CPU ray cast, " << fixed(cast_ms, 0)
       << " ms. Original triangles culled (a vertex within the guard of the degenerate set), by node:";
    for (const auto& [node, count] : culled_by_node) {
        md << " " << node << " " << count << ";";
    }
    md << "\n\n" << table.str();
    report.markdown = md.str();
    return report;
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
               "options:\n"
               "  --grids LIST        grid sizes N (N x N tiles), comma-separated (default 4,8,16,32)\n"
               "  --supersampling K   reference texture resolution / frame resolution, 1..8 (default 4)\n"
               "  --runs N            timed repetitions per frame, median reported, 1..100 (default 5)\n"
               "  --lens-power P, --scene FILE, --camera NAME|INDEX, --size WxH, --backend B,\n"
               "  --depth D, --out DIR as for frustum-demo render (see frustum-demo --help)\n"
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
           "options:\n"
           "  --edges LIST        subdivision edge lengths in metres, comma-separated, 0 = none\n"
           "                      (default 0,1,0.5,0.25,0.1)\n"
           "  --runs N            timed repetitions per frame, median reported, 1..100 (default 5)\n"
           "  --slit M            depth (m) where the left and right planes meet (default 2.6)\n"
           "  --pivot M           depth (m) where they cut the camera's side planes (default 8)\n"
           "  --scene FILE, --camera NAME|INDEX, --size WxH, --backend B, --depth D, --out DIR\n"
           "                      as for frustum-demo render (see frustum-demo --help)\n"
           "\n"
           "Writes DIR/nonaffine-naive.png, DIR/nonaffine-cull.png, DIR/nonaffine-<edge>m.png,\n"
           "DIR/nonaffine-reference.png, DIR/nonaffine-diff-cull.png (culled, not subdivided, vs the\n"
           "reference, x 4) and DIR/nonaffine-diff.png (the last row vs the reference, x 4).\n";
}

std::variant<HelpRequest, WarpReportRequest, Failure> parse_warp_report(const std::vector<std::string>& args) {
    WarpReportRequest request;
    const std::string command = args.empty() ? std::string() : args[0];
    request.kind = command == "lens-report" ? WarpReportRequest::Kind::Lens : WarpReportRequest::Kind::NonAffine;
    request.grids = {4, 8, 16, 32};
    request.max_edges_m = {0.0f, 1.0f, 0.5f, 0.25f, 0.1f};
    const std::string hint = " (see frustum-demo " + command + " --help)";
    std::vector<std::string> forwarded{"render"};
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& name = args[i];
        if (name == "--help" || name == "-h") {
            return HelpRequest{};
        }
        const bool own = name == "--grids" || name == "--edges" || name == "--supersampling" || name == "--runs" ||
                         name == "--slit" || name == "--pivot";
        if (!own) {
            if (name == "--effect" || name == "--tiles" || name == "--mirror" || name == "--lens-grid") {
                return usage(name + " does not apply to " + command + hint);
            }
            forwarded.push_back(name);
            continue;
        }
        if (i + 1 >= args.size()) {
            return usage(name + " needs a value" + hint);
        }
        const std::string& value = args[++i];
        const std::string got = ", got '" + value + "'";
        if (name == "--grids" && request.kind == WarpReportRequest::Kind::Lens) {
            auto grids = parse_list<int>(value, [](int g) { return g >= 1 && g <= kMaxLensGrid; });
            if (!grids) {
                return usage("--grids must be a comma-separated list of whole numbers in 1.." +
                             std::to_string(kMaxLensGrid) + got);
            }
            request.grids = *grids;
        } else if (name == "--edges" && request.kind == WarpReportRequest::Kind::NonAffine) {
            auto edges = parse_list<float>(value, [](float e) { return e >= 0.0f && e <= 100.0f; });
            if (!edges) {
                return usage("--edges must be a comma-separated list of lengths in [0, 100] metres" + got);
            }
            request.max_edges_m = *edges;
        } else if (name == "--supersampling" && request.kind == WarpReportRequest::Kind::Lens) {
            auto k = parse_list<int>(value, [](int v) { return v >= 1 && v <= 8; });
            if (!k || k->size() != 1) {
                return usage("--supersampling must be a whole number in 1..8" + got);
            }
            request.supersampling = k->front();
        } else if ((name == "--slit" || name == "--pivot") && request.kind == WarpReportRequest::Kind::NonAffine) {
            auto depth = parse_list<float>(value, [](float d) { return d > 0.0f && d <= 1000.0f; });
            if (!depth || depth->size() != 1) {
                return usage(name + " must be a depth in (0, 1000] metres" + got);
            }
            (name == "--slit" ? request.slit_depth_m : request.pivot_depth_m) = depth->front();
        } else if (name == "--runs") {
            auto runs = parse_list<int>(value, [](int v) { return v >= 1 && v <= 100; });
            if (!runs || runs->size() != 1) {
                return usage("--runs must be a whole number in 1..100" + got);
            }
            request.runs = runs->front();
        } else {
            return usage(name + " does not apply to " + command + hint);
        }
    }
    auto parsed = parse_command_line(forwarded);
    if (auto* failure = std::get_if<Failure>(&parsed)) {
        return *failure;
    }
    if (std::holds_alternative<HelpRequest>(parsed)) {
        return HelpRequest{};
    }
    request.render = std::get<RenderRequest>(parsed);
    const int smaller_side = std::min(request.render.width_px, request.render.height_px);
    for (int grid : request.grids) {
        if (request.kind == WarpReportRequest::Kind::Lens && grid > smaller_side) {
            return usage("--grids " + std::to_string(grid) + " needs at least one pixel per tile, but the image is " +
                         std::to_string(request.render.width_px) + "x" + std::to_string(request.render.height_px));
        }
    }
    return request;
}

std::variant<WarpReport, Failure> run_warp_report(const WarpReportRequest& request, const Reporter& reporter) {
    if (auto status = prepare_output_dir(request.render.out_dir); !status) {
        return runtime(status.error());
    }
    auto session = open_session(request.render, reporter);
    if (!session) {
        return runtime(session.error());
    }
    return request.kind == WarpReportRequest::Kind::Lens ? lens_report(request, **session, reporter)
                                                         : nonaffine_report(request, **session, reporter);
}

} // namespace demo
