#include "demo/run_render.hpp"

#include "demo/output_dir.hpp"
#include "demo/poster_file.hpp"
#include "demo/sheet_labels.hpp"

#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <image/contact_sheet.hpp>
#include <image/png.hpp>
#include <plan/camera.hpp>
#include <plan/curved_mirror.hpp>
#include <plan/mirror_placement.hpp>
#include <plan/number_text.hpp>
#include <render/poster.hpp>
#include <render/renderer.hpp>
#include <plan/scene_fit.hpp>
#include <plan/view_tree.hpp>
#include <render/stereo_render.hpp>
#include <scene/load_gltf.hpp>

#include <image/png_stream.hpp>

#include <cstdio>
#include <memory>
#include <optional>
#include <utility>

namespace demo {
std::string depth_summary(const render::Renderer& renderer, render::DepthPath path) {
    return renderer.gpu_depth_range(path) == frustum::DepthRange::ZeroToOne
               ? "depth: [0, 1] clip range via clip control"
               : "depth: matrices converted to the [-1, 1] clip range";
}

namespace {

std::string size_text(int width_px, int height_px) { return std::to_string(width_px) + "x" + std::to_string(height_px); }

// "41.2 s, 0.41 Mpx/s (render 30.1 s, read-back 4.9 s, PNG 6.2 s; CPU: render 55.0 s, read-back 6.3 s, PNG 6.1 s)"
std::string timing_text(const PosterTiming& timing, const render::PosterLayout& layout) {
    const double mpx = double(layout.width_px) * layout.height_px / 1e6;
    char text[240];
    std::snprintf(text, sizeof text,
                  "%.2f s, %.2f Mpx/s (render %.2f s, read-back %.2f s, PNG %.2f s; CPU: render %.2f s, "
                  "read-back %.2f s, PNG %.2f s)",
                  timing.total_s, timing.total_s > 0.0 ? mpx / timing.total_s : 0.0, timing.rendering.wall_s,
                  timing.read_back.wall_s, timing.compression.wall_s, timing.rendering.cpu_s, timing.read_back.cpu_s,
                  timing.compression.cpu_s);
    return text;
}

// The frame as a poster (render::render_poster(), streamed to the PNG) with
// --poster-tile or when one target of the context cannot hold it; nullopt:
// a direct render, as always. Stereo: both eyes' posters side by side
// (render::stereo_poster_layout(): no tile straddles the eyes).
std::variant<std::optional<render::PosterLayout>, Failure> choose_poster(const gl::Functions& fn,
                                                                          const RenderRequest& request,
                                                                          bool stereo) {
    const int w = request.width_px;
    const int h = request.height_px;
    const bool direct_size = w <= kMaxDirectSidePx && h <= kMaxDirectSidePx;
    const auto whole = render::poster_layout(fn, w, h, std::pair<int, int>(w, h));
    if (direct_size && whole && !request.poster) {
        return std::optional<render::PosterLayout>();
    }
    auto layout = stereo ? render::stereo_poster_layout(fn, w, h, request.poster_tile_px)
                         : render::poster_layout(fn, w, h, request.poster_tile_px);
    if (!layout) {
        return usage("--poster-tile: " + layout.error());
    }
    return std::optional<render::PosterLayout>(*layout);
}

// What every effect of one `render` shares: the open session (on the heap:
// GL objects point to its members), the frame's options, the stereo rig
// and, for a poster, its layout.
struct RenderSetup {
    std::unique_ptr<Session> session;
    render::RenderOptions options;
    std::optional<plan::StereoRig> stereo;
    std::optional<render::PosterLayout> layout;
};

// The options of every frame: the resolved effect values, the size, the
// depth path and the MSAA samples the context grants.
std::variant<render::RenderOptions, Failure> frame_options(const RenderRequest& request, const Session& session,
                                                           const Reporter& reporter) {
    const gl::Functions& fn = *session.fn;
    auto samples = gl::choose_samples(fn, request.msaa_samples);
    if (!samples) {
        return runtime("--msaa " + std::to_string(request.msaa_samples) + ": " + samples.error());
    }
    if (request.verbose) {
        reporter.note("msaa: " + std::to_string(*samples) + " samples (GL_MAX_SAMPLES=" +
                      std::to_string(gl::max_samples(fn)) + ")");
        reporter.note(depth_summary(*session.renderer, request.depth));
        reporter.note("camera: " + session.cameras->main.name + ", overview: " + session.cameras->overview.name);
    }
    render::RenderOptions options;
    static_cast<plan::EffectParams&>(options) = session.effects.params;
    options.width_px = request.width_px;
    options.height_px = request.height_px;
    options.depth = request.depth;
    options.msaa_samples = *samples;
    return options;
}

// The output folder, the session, the options, the stereo rig (its eyes
// checked once, not once per effect) and the poster layout, or the first
// failure.
std::variant<RenderSetup, Failure> open_render(const RenderRequest& request, const Reporter& reporter) {
    if (request.stereo && request.width_px % 2 != 0) {
        return Failure{ExitStatus::UsageError, "--stereo needs an even width (two eyes side by side), got --size " +
                                                   size_text(request.width_px, request.height_px)};
    }
    if (auto status = prepare_output_dir(request.out_dir); !status) {
        return runtime(status.error());
    }
    g_activity = "loading the scene";
    RenderSetup setup;
    setup.session = std::make_unique<Session>();
    const Session& session = *setup.session;
    if (auto failure = setup.session->open(request, reporter)) {
        return *failure;
    }
    g_activity = "rendering";
    auto options = frame_options(request, session, reporter);
    if (auto* failure = std::get_if<Failure>(&options)) {
        return *failure;
    }
    setup.options = std::get<render::RenderOptions>(std::move(options));
    const frustum::MatrixPair<float>& main = session.cameras->main.pair;
    setup.stereo = plan::stereo_rig(request, main, session.scene);
    if (setup.stereo) {
        if (auto eyes = plan::stereo_eyes(main, *setup.stereo); !eyes) {
            return runtime(eyes.error());
        }
        if (request.verbose) {
            reporter.note("stereo: ipd " + plan::number_text(setup.stereo->ipd_m) + " m, convergence " +
                          plan::number_text(setup.stereo->convergence_m) + " m");
        }
    }
    auto poster = choose_poster(*session.fn, request, setup.stereo.has_value());
    if (auto* failure = std::get_if<Failure>(&poster)) {
        return *failure;
    }
    setup.layout = std::get<0>(poster);
    if (setup.layout && request.verbose) {
        const render::PosterLayout& layout = *setup.layout;
        reporter.note("poster: " + size_text(layout.width_px, layout.height_px) + " in tiles of " +
                      size_text(layout.tile_width_px, layout.tile_height_px) + ", streamed to PNG" +
                      (setup.stereo ? ", each eye " + size_text(layout.width_px / 2, layout.height_px)
                                    : std::string()));
    }
    return setup;
}

// The files a run writes: each path kept, and "[k/n] name" on the progress
// line when several effects (and their contact sheet) are written.
struct RunFiles {
    const RenderRequest& request;
    const Reporter& reporter;
    RenderRun& run;
    bool several = false;
    std::size_t total = 0;

    void written(const std::string& path, const std::string& name) {
        run.written_paths.push_back(path);
        if (several) {
            reporter.progress("[" + std::to_string(run.written_paths.size()) + "/" + std::to_string(total) + "] " +
                              name);
        }
    }
    frustum::Status write(const image::Image& picture, const std::string& name) {
        const std::string path = request.out_dir + "/" + name;
        if (auto status = image::write_png(picture, path); !status) {
            return status;
        }
        written(path, name);
        return {};
    }
};

// One effect drawn and written: its picture (the direct render, or a
// poster's thumbnail), or the effect's own error, or a failure that ends
// the whole run (a file that cannot be written).
struct EffectOutcome {
    std::optional<image::Image> picture;
    std::string error;
    std::optional<Failure> abort;
};

EffectOutcome draw_effect(plan::Effect effect, const RenderSetup& setup, RunFiles& files) {
    const RenderRequest& request = files.request;
    const Session& session = *setup.session;
    const std::string name(plan::to_string(effect));
    if (request.verbose && effect == plan::Effect::Recursion) { // where the recursion ends (view_tree.hpp)
        const auto end = plan::recursion_end_note(plan::cameras_for(effect, *session.cameras).main.pair,
                                                  session.scene.world_bounds,
                                                  plan::instance_boxes(session.scene), setup.options.recursion_links,
                                                  setup.options.recursion_depth, request.width_px, request.height_px);
        if (end && *end) {
            files.reporter.note(**end);
        }
    }
    EffectOutcome outcome;
    if (setup.layout) {
        PosterJob job{effect, *setup.layout, setup.stereo, request.out_dir + "/" + name + ".png",
                      image::kStreamZlibLevel, files.reporter.status};
        auto file = write_poster(*session.renderer, *session.cameras, setup.options, job);
        if (!file) {
            outcome.error = file.error();
            return outcome;
        }
        if (request.verbose) {
            files.reporter.note("poster: " + name + ".png: " + timing_text(file->timing, *setup.layout));
        }
        files.written(job.path, name + ".png");
        outcome.picture = std::move(file->thumbnail);
        return outcome;
    }
    auto drawn = setup.stereo
                     ? render::render_stereo(*session.renderer, effect, *session.cameras, setup.options, *setup.stereo)
                     : session.renderer->render(effect, *session.cameras, setup.options);
    if (!drawn) {
        outcome.error = drawn.error();
    } else if (auto status = files.write(*drawn, name + ".png"); !status) {
        outcome.abort = runtime(status.error());
    } else {
        outcome.picture = std::move(*drawn);
    }
    return outcome;
}

// The contact sheet of the effects drawn (none: no sheet).
std::optional<Failure> write_contact_sheet(const std::vector<std::pair<std::string, image::Image>>& images,
                                           RunFiles& files) {
    std::vector<std::pair<std::string, const image::Image*>> cells;
    for (const auto& [name, picture] : images) {
        cells.emplace_back(name, &picture);
    }
    if (cells.empty()) {
        return std::nullopt; // every effect failed: nothing to put on a sheet
    }
    auto sheet = image::contact_sheet(cells, 2);
    if (!sheet) {
        return runtime(sheet.error());
    }
    if (auto status = files.write(*sheet, "contact_sheet.png"); !status) {
        return runtime(status.error());
    }
    return std::nullopt;
}

std::variant<RenderRun, Failure> render_into_dir(const RenderRequest& request, const Reporter& reporter) {
    auto opened = open_render(request, reporter);
    if (auto* failure = std::get_if<Failure>(&opened)) {
        return *failure;
    }
    const RenderSetup& setup = std::get<RenderSetup>(opened);
    const Session& session = *setup.session;
    RenderRun run;
    const bool several = request.effects.size() > 1;
    RunFiles files{request, reporter, run, several, request.effects.size() + (several ? 1 : 0)};
    std::vector<std::pair<std::string, image::Image>> images;
    for (plan::Effect effect : request.effects) {
        EffectOutcome outcome = draw_effect(effect, setup, files);
        if (outcome.abort) {
            return *outcome.abort;
        }
        const std::string name(plan::to_string(effect));
        if (!outcome.picture) {
            const std::string failure = name + ": " + outcome.error;
            if (!several || (setup.layout && outcome.error.rfind("image::PngStream", 0) == 0)) {
                return runtime(failure);
            }
            run.failed_effects.push_back(failure);
            reporter.progress("[-/" + std::to_string(files.total) + "] " + name + " failed: " + outcome.error);
            continue;
        }
        if (several) {
            const plan::NamedCamera drawn_with = plan::cameras_for(effect, *session.cameras).main;
            std::vector<CaptionLine> caption =
                effect_caption(effect, setup.options, drawn_with.name, drawn_with.pair, session.scene);
            if (plan::effect_needs_finite_eye(effect) && session.cameras->perspective_twin) {
                caption.push_back({"from " + drawn_with.name});
            }
            images.emplace_back(name, with_caption(*outcome.picture, caption));
        }
    }
    g_activity = "writing the contact sheet";
    if (several) {
        if (auto failure = write_contact_sheet(images, files)) {
            return *failure;
        }
    }
    return run;
}

} // namespace

const char* g_activity = "starting";

std::variant<RenderRun, Failure> run_render(const RenderRequest& request, const Reporter& reporter) {
    const std::vector<std::string> created = missing_folders(request.out_dir);
    auto outcome = render_into_dir(request, reporter);
    if (std::holds_alternative<Failure>(outcome)) {
        remove_empty_folders(created);
    }
    return outcome;
}

} // namespace demo
