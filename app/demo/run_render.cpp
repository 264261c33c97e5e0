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

// "41.2 s, 0.41 Mpx/s (render and read-back 35.0 s, PNG 6.2 s; CPU: render and read-back 61.3 s, PNG 6.1 s)"
std::string timing_text(const PosterTiming& timing, const render::PosterLayout& layout) {
    const double mpx = double(layout.width_px) * layout.height_px / 1e6;
    char text[200];
    std::snprintf(text, sizeof text,
                  "%.2f s, %.2f Mpx/s (render and read-back %.2f s, PNG %.2f s; CPU: render and read-back %.2f s, "
                  "PNG %.2f s)",
                  timing.total_s, timing.total_s > 0.0 ? mpx / timing.total_s : 0.0, timing.render_and_read_back_s,
                  timing.compression_s, timing.render_and_read_back_cpu_s, timing.compression_cpu_s);
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
    if (direct_size && whole && !request.poster_tile_px) {
        return std::optional<render::PosterLayout>();
    }
    auto layout = stereo ? render::stereo_poster_layout(fn, w, h, request.poster_tile_px)
                         : render::poster_layout(fn, w, h, request.poster_tile_px);
    if (!layout) {
        return usage("--poster-tile: " + layout.error());
    }
    return std::optional<render::PosterLayout>(*layout);
}

std::variant<RenderRun, Failure> render_into_dir(const RenderRequest& request, const Reporter& reporter) {
    if (request.stereo && request.width_px % 2 != 0) {
        return Failure{ExitStatus::UsageError, "--stereo needs an even width (two eyes side by side), got --size " +
                                                   std::to_string(request.width_px) + "x" +
                                                   std::to_string(request.height_px)};
    }
    if (auto status = prepare_output_dir(request.out_dir); !status) {
        return runtime(status.error());
    }
    g_activity = "loading the scene";
    auto owned = std::make_unique<Session>(); // on the heap: GL objects point to its members
    Session& session = *owned;
    if (auto failure = session.open(request, reporter)) {
        return *failure;
    }
    g_activity = "rendering";
    const plan::Cameras* cameras = &*session.cameras;
    scene::Scene* scene = &session.scene;
    const gl::Functions* fn = session.fn.get();
    render::Renderer* renderer = &*session.renderer;
    auto samples = gl::choose_samples(*fn, request.msaa_samples);
    if (!samples) {
        return runtime("--msaa " + std::to_string(request.msaa_samples) + ": " + samples.error());
    }
    if (request.verbose) {
        reporter.note("msaa: " + std::to_string(*samples) + " samples (GL_MAX_SAMPLES=" +
                      std::to_string(gl::max_samples(*fn)) + ")");
        reporter.note(depth_summary(*renderer, request.depth));
        reporter.note("camera: " + cameras->main.name + ", overview: " + cameras->overview.name);
    }

    const std::optional<plan::StereoRig> stereo = plan::stereo_rig(request, cameras->main.pair, *scene);
    if (stereo) { // the rig's bounds once, not once per effect
        if (auto eyes = plan::stereo_eyes(cameras->main.pair, *stereo); !eyes) {
            return runtime(eyes.error());
        }
    }
    if (stereo && request.verbose) {
        reporter.note("stereo: ipd " + plan::number_text(stereo->ipd_m) + " m, convergence " +
                      plan::number_text(stereo->convergence_m) + " m");
    }

    render::RenderOptions options;
    static_cast<plan::EffectParams&>(options) = session.effects.params;
    options.width_px = request.width_px;
    options.height_px = request.height_px;
    options.depth = request.depth;
    options.msaa_samples = *samples;

    const bool several = request.effects.size() > 1;
    const std::size_t total = request.effects.size() + (several ? 1 : 0);
    RenderRun run;
    std::vector<std::pair<std::string, image::Image>> images;
    const auto write = [&](const image::Image& picture, const std::string& name) -> frustum::Status {
        const std::string path = request.out_dir + "/" + name;
        if (auto status = image::write_png(picture, path); !status) {
            return status;
        }
        run.written_paths.push_back(path);
        if (several) {
            reporter.progress("[" + std::to_string(run.written_paths.size()) + "/" + std::to_string(total) + "] " +
                              name);
        }
        return {};
    };
    auto poster = choose_poster(*fn, request, stereo.has_value());
    if (auto* failure = std::get_if<Failure>(&poster)) {
        return *failure;
    }
    const std::optional<render::PosterLayout> layout = std::get<0>(poster);
    if (layout && request.verbose) {
        reporter.note("poster: " + size_text(layout->width_px, layout->height_px) + " in tiles of " +
                      size_text(layout->tile_width_px, layout->tile_height_px) + ", streamed to PNG" +
                      (stereo ? ", each eye " + size_text(layout->width_px / 2, layout->height_px) : std::string()));
    }
    for (plan::Effect effect : request.effects) {
        const std::string name(plan::to_string(effect));
        if (request.verbose && effect == plan::Effect::Recursion) { // where the recursion ends (view_tree.hpp)
            const auto end = plan::recursion_end_note(cameras->main.pair, scene->world_bounds,
                                                      plan::instance_boxes(*scene), options.recursion_links,
                                                      options.recursion_depth, request.width_px, request.height_px);
            if (end && *end) {
                reporter.note(**end);
            }
        }
        std::optional<image::Image> picture; // a direct render; a poster leaves only its thumbnail
        std::string error;
        if (layout) {
            PosterJob job{effect, *layout, stereo, request.out_dir + "/" + name + ".png", image::kStreamZlibLevel,
                          reporter.status};
            auto file = write_poster(*renderer, *cameras, options, job);
            if (file) {
                if (request.verbose) {
                    reporter.note("poster: " + name + ".png: " + timing_text(file->timing, *layout));
                }
                run.written_paths.push_back(job.path);
                if (several) {
                    reporter.progress("[" + std::to_string(run.written_paths.size()) + "/" + std::to_string(total) +
                                      "] " + name + ".png");
                }
                picture = std::move(file->thumbnail);
            } else {
                error = file.error();
            }
        } else {
            auto drawn = stereo ? render::render_stereo(*renderer, effect, *cameras, options, *stereo)
                                : renderer->render(effect, *cameras, options);
            if (drawn) {
                if (auto status = write(*drawn, name + ".png"); !status) {
                    return runtime(status.error());
                }
                picture = std::move(*drawn);
            } else {
                error = drawn.error();
            }
        }
        if (!picture) {
            const std::string failure = name + ": " + error;
            if (!several || (layout && error.rfind("image::PngStream", 0) == 0)) {
                return runtime(failure);
            }
            run.failed_effects.push_back(failure);
            reporter.progress("[-/" + std::to_string(total) + "] " + name + " failed: " + error);
            continue;
        }
        if (several) {
            images.emplace_back(name, with_caption(*picture, effect_caption(effect, options, cameras->main.name,
                                                                            cameras->main.pair, *scene)));
        }
    }
    g_activity = "writing the contact sheet";
    if (several) {
        std::vector<std::pair<std::string, const image::Image*>> cells;
        for (const auto& [name, picture] : images) {
            cells.emplace_back(name, &picture);
        }
        if (cells.empty()) {
            return run; // every effect failed: nothing to put on a sheet
        }
        auto sheet = image::contact_sheet(cells, 2);
        if (!sheet) {
            return runtime(sheet.error());
        }
        if (auto status = write(*sheet, "contact_sheet.png"); !status) {
            return runtime(status.error());
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
