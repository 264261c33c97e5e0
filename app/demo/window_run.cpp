#include "demo/window_run.hpp"

#include "demo/run_render.hpp"

#include <gl/functions.hpp>
#include <gl/glfw_egl_window.hpp>
#include <gl/window_framebuffer.hpp>
#include <image/png.hpp>
#include <gl/offscreen_target.hpp>
#include <plan/camera.hpp>
#include <render/renderer.hpp>
#include <window/controls.hpp>
#include <window/frame.hpp>
#include <window/frame_clock.hpp>
#include <window/frame_painter.hpp>
#include <window/mirror_pose.hpp>
#include <window/orbit_camera.hpp>

#include <algorithm>
#include <chrono>
#include <optional>
#include <utility>

namespace demo {
namespace {


// Everything one frame loop needs, made once: the session (demo/session.hpp)
// with the window as its context, and the painter, which dies before them.
struct WindowSession : Session {
    gl::GlfwEglWindow* window = nullptr; // the session's context
    std::optional<window::FramePainter> painter;
    EffectSetup effects; // the effect options, with what they leave unset derived from the scene
};

std::variant<std::unique_ptr<WindowSession>, Failure> open_session(const WindowRequest& request,
                                                                  const std::function<void(std::string_view)>& note) {
    auto session = std::make_unique<WindowSession>();
    if (auto failure = load_session(*session, request, false)) {
        return *failure;
    }
    const Reporter reporter{note, note};
    session->effects = setup_effects(session->scene, request, reporter);
    gl::WindowOptions options;
    options.title = window::window_title(request.effects.front(), std::nullopt);
    options.width = request.width_px;
    options.height = request.height_px;
    options.vsync = !request.frames; // scripted runs go as fast as they can
    options.context = context_options(request, note);
    const auto open_window = [&]() -> frustum::Result<std::unique_ptr<gl::Context>> {
        auto window = gl::GlfwEglWindow::create(options);
        if (!window) {
            return frustum::Error{"cannot open a window: " + window.error() +
                                  "; use `frustum-demo render` for offscreen images"};
        }
        session->window = window->get();
        return std::unique_ptr<gl::Context>(std::move(*window));
    };
    if (auto failure = start_gl(*session, request, reporter, open_window)) {
        return *failure;
    }
    auto samples = gl::choose_samples(*session->fn, request.msaa_samples);
    if (!samples) {
        return runtime("--msaa " + std::to_string(request.msaa_samples) + ": " + samples.error());
    }
    if (request.verbose) {
        note("msaa: " + std::to_string(*samples) + " samples (GL_MAX_SAMPLES=" +
             std::to_string(gl::max_samples(*session->fn)) + ")");
    }
    auto painter = window::FramePainter::create(*session->fn);
    if (!painter) {
        return runtime(painter.error());
    }
    session->painter.emplace(std::move(*painter));
    return session;
}

window::ViewerState initial_state(const WindowRequest& request) {
    window::ViewerState state;
    state.effect = request.effects.front();
    state.tile_columns = request.tile_columns;
    state.tile_rows = request.tile_rows;
    state.mirror_method = request.mirror;
    state.lens_power = request.lens_power; // --lens-power: the start; [ and ] change it
    state.show_help = request.help_overlay;
    state.show_inset = request.inset;
    state.msaa_samples = request.msaa_samples;
    return state;
}

frustum::Status save_screenshot(const gl::Functions& fn, const gl::FramebufferSize& size, const std::string& path) {
    auto pixels = gl::read_window_pixels(fn, size.width_px, size.height_px);
    if (!pixels) {
        return pixels.take_error();
    }
    return image::write_png(*pixels, path);
}

// The frame's render options from the effect settings (the frame sets
// size, tiles, mirror method and lens power from the viewer state).
void apply_effect_settings(const EffectSetup& setup, window::Frame& frame, int width_px, int height_px) {
    render::RenderOptions& o = frame.options;
    o.curved = setup.options.curved;
    o.fit = setup.options.fit;
    o.tile_borders = setup.options.tile_borders;
    o.fog = setup.options.fog; // --fog (the plain and mirror effects)
    o.lens_grid = std::min(setup.options.lens_grid, std::min(width_px, height_px));
}

} // namespace

std::variant<WindowRun, Failure> run_window(const WindowRequest& request,
                                            const std::function<void(std::string_view)>& note) {
    auto opened = open_session(request, note);
    if (auto* failure = std::get_if<Failure>(&opened)) {
        return *failure;
    }
    WindowSession& s = *std::get<std::unique_ptr<WindowSession>>(opened);
    const std::vector<int> attachments = window::mirror_attachments(s.scene);
    const window::OrbitProjection projection = window::orbit_projection(s.scene, s.camera_index);
    window::Controls controls(window::control_scene(s.scene));
    window::ViewerState state = initial_state(request);
    window::MirrorPose applied_pose;
    window::FrameClock clock;
    std::optional<double> frame_ms;
    render::Effect titled_effect = state.effect;
    gl::FramebufferSize size = s.window->framebuffer_size();
    std::optional<render::Cameras> cameras;
    WindowRun run;
    render::Effect shown_effect = state.effect; // the last effect drawn
    std::optional<std::string> notice;          // why an effect was refused, in the overlay
    std::size_t keys_pressed = 0;               // of request.keys, one per pass of the loop

    while (!s.window->should_close()) {
        const bool minimized = size.width_px < 1 || size.height_px < 1;
        std::vector<gl::InputEvent> events = minimized ? s.window->wait_events() : s.window->poll_events();
        if (keys_pressed < request.keys.size()) {
            events.emplace_back(request.keys[keys_pressed++]);
        }
        // The framebuffer size (not the window size) sets the frame, its aspect and the tiles.
        for (const gl::InputEvent& event : events) {
            if (const auto* resized = std::get_if<gl::FramebufferResized>(&event)) {
                size = {resized->width_px, resized->height_px};
                cameras.reset();
            }
        }
        if (size.width_px < 1 || size.height_px < 1) {
            continue;
        }
        // Stereo: cameras, frame and options are one eye's, half the width.
        const int eye_width_px = request.stereo ? std::max(1, size.width_px / 2) : size.width_px;
        if (!cameras) {
            auto made = render::make_cameras(s.scene, s.camera_index, eye_width_px, size.height_px);
            if (!made) {
                return runtime(made.error());
            }
            cameras = std::move(*made);
        }
        for (const gl::InputEvent& event : events) {
            controls.apply(event, cameras->main.pair, state);
        }
        if (state.quit) {
            s.window->request_close();
            break;
        }
        if (s.scene.mirror && state.mirror != applied_pose) {
            if (auto moved = s.renderer->move_mirror(window::mirror_motion(*s.scene.mirror, state.mirror), attachments);
                !moved) {
                return runtime(moved.error());
            }
            applied_pose = state.mirror;
        }
        auto frame = window::make_frame(state, *cameras, projection, s.scene.world_bounds, eye_width_px,
                                        size.height_px);
        if (!frame) {
            return runtime(frame.error());
        }
        apply_effect_settings(s.effects, *frame, eye_width_px, size.height_px);
        frame->stereo = stereo_rig(request, frame->cameras.main.pair, s.scene);
        if (notice) {
            frame->text.insert(frame->text.begin(), *notice);
        }
        frustum::Status painted = frame->effect == render::Effect::Curved && s.effects.sagitta_error
                                      ? frustum::Status(frustum::Error{*s.effects.sagitta_error})
                                      : s.painter->paint(*s.renderer, *frame, size.width_px, size.height_px);
        if (!painted) {
            // Not for this scene or camera: keep the previous effect (plain
            // when that one fails now too, then no inset), say why, go on.
            const std::string name(render::to_string(frame->effect));
            if (frame->effect == render::Effect::Plain && !frame->inset) {
                return runtime(painted.error());
            }
            if (frame->effect != shown_effect) {
                state.effect = shown_effect;
            } else if (frame->effect != render::Effect::Plain) {
                state.effect = render::Effect::Plain;
            } else {
                state.show_inset = false;
            }
            notice = (frame->effect == render::Effect::Plain ? std::string("inset") : "effect " + name) +
                     " not drawn: " + painted.error() + "; showing " + std::string(render::to_string(state.effect));
            note(*notice);
            continue;
        }
        if (state.effect != shown_effect) {
            notice.reset(); // a new effect was drawn: the old reason no longer applies
        }
        shown_effect = state.effect;
        ++run.frames_drawn;
        const bool last = request.frames && run.frames_drawn >= *request.frames;
        if (last && request.screenshot) {
            if (auto saved = save_screenshot(*s.fn, size, *request.screenshot); !saved) {
                return runtime(saved.error());
            }
            run.written_paths.push_back(*request.screenshot);
        }
        s.window->swap_buffers();
        if (auto mean = clock.tick(std::chrono::steady_clock::now()); mean || titled_effect != state.effect) {
            frame_ms = mean ? mean : frame_ms;
            titled_effect = state.effect;
            s.window->set_title(window::window_title(state.effect, frame_ms));
        }
        if (last) {
            break;
        }
    }
    return run;
}

} // namespace demo
