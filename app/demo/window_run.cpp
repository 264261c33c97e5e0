#include "demo/window_run.hpp"

#include "demo/poster_file.hpp"
#include "demo/run_render.hpp"
#include "demo/window_panel.hpp"

#include <gl/functions.hpp>
#include <gl/glfw_egl_window.hpp>
#include <gl/window_framebuffer.hpp>
#include <image/png.hpp>
#include <image/png_stream.hpp>
#include <gl/offscreen_target.hpp>
#include <plan/camera.hpp>
#include <render/poster.hpp>
#include <render/renderer.hpp>
#include <window/controls.hpp>
#include <window/frame.hpp>
#include <window/frame_clock.hpp>
#include <window/fragment_counter.hpp>
#include <window/frame_painter.hpp>
#include <window/frame_step.hpp>
#include <window/gpu_timer.hpp>
#include <window/imgui_layer.hpp>
#include <window/key_help.hpp>
#include <window/live_numbers.hpp>
#include <window/mirror_pose.hpp>
#include <window/orbit_camera.hpp>

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <utility>

namespace demo {
namespace {

// The window's [ and ] keys stop at --lens-power's bound.
// The panel's screenshot button without --screenshot writes here (the current folder).
constexpr const char* kPanelScreenshot = "frustum-window.png";

static_assert(window::kMaxLensPower == kMaxLensPower, "window lens power keys and --lens-power disagree");

// Everything one frame loop needs, made once: the session (demo/session.hpp)
// with the window as its context, and the painter, which dies before them.
struct WindowSession : Session {
    gl::GlfwEglWindow* window = nullptr; // the session's context
    std::optional<window::FramePainter> painter;
    std::unique_ptr<window::ImGuiLayer> imgui; // the panel and the key help
    std::optional<window::GpuTimer> timer;
    std::optional<window::FragmentCounter> fragments; // desktop GL (--context gl) only
};

std::variant<std::unique_ptr<WindowSession>, Failure> open_session(const WindowRequest& request,
                                                                  const std::function<void(std::string_view)>& note) {
    auto session = std::make_unique<WindowSession>();
    const Reporter reporter{note, note};
    gl::WindowOptions options;
    options.title = window::window_title(request.effects.front(), std::nullopt);
    options.width = request.width_px;
    options.height = request.height_px;
    options.vsync = !request.frames; // scripted runs go as fast as they can
    options.api = request.context_api;
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
    OpenOptions how;
    how.cameras_at_size = false;  // per framebuffer size, each frame
    how.refuse_explicit = false;  // the window refuses only the curved effect (effects.refused, in run_window)
    how.make_context = open_window;
    if (auto failure = session->open(request, reporter, how)) {
        return *failure;
    }
    auto samples = gl::choose_samples(*session->fn, request.msaa_samples);
    if (!samples) {
        return runtime("--msaa " + std::to_string(request.msaa_samples) + ": " + samples.error());
    }
    if (request.verbose) {
        note("msaa: " + std::to_string(*samples) + " samples (GL_MAX_SAMPLES=" +
             std::to_string(gl::max_samples(*session->fn)) + ")");
        note(depth_summary(*session->renderer, request.depth));
    }
    auto painter = window::FramePainter::create(*session->fn);
    if (!painter) {
        return runtime(painter.error());
    }
    session->painter.emplace(std::move(*painter));
    auto imgui = window::ImGuiLayer::create(*session->fn);
    if (!imgui) {
        return runtime(imgui.error());
    }
    session->imgui = std::move(*imgui);
    session->timer.emplace(*session->window, *session->fn);
    session->fragments.emplace(*session->window, *session->fn);
    return session;
}

// The settings the viewer state holds (the keys change them afterwards):
// the effect values as resolved for the session's scene, and the effect,
// MSAA and depth path of the settings.
void hold(const plan::EffectParams& params, const Settings& settings, window::ViewerState& state) {
    static_cast<plan::EffectParams&>(state) = params;
    state.effect = settings.effects.front();
    state.msaa_samples = settings.msaa_samples;
    state.depth = settings.depth;
}

window::ViewerState initial_state(const WindowRequest& request, const WindowSession& s) {
    window::ViewerState state;
    hold(s.effects.params, request, state);
    state.show_help = request.help_overlay;
    state.show_panel = request.panel;
    state.show_inset = request.inset;
    return state;
}

// Settings from the panel, or for a scene file it loaded: resolved for the
// session's scene as at start-up (plan::resolve_effects()), the mirror
// left where the scene has it (mirror_kept()), into the viewer state.
void take_settings(const Settings& settings, WindowSession& s, window::ViewerState& state) {
    s.effects = plan::resolve_effects(settings, s.scene);
    hold(s.effects.params, settings, state);
}

frustum::Status save_screenshot(const gl::Functions& fn, const gl::FramebufferSize& size, const std::string& path) {
    auto pixels = gl::read_window_pixels(fn, size.width_px, size.height_px);
    if (!pixels) {
        return pixels.take_error();
    }
    return image::write_png(*pixels, path);
}

// The panel's screenshot at `scale` x the window (> 1): the frame's view,
// effect and values drawn again as a poster, streamed to
// "frustum-window-<scale>x.png" (without the inset, the panel and the help).
// A stereo frame (its cameras one eye's) gives both eyes side by side, as
// render's stereo posters.
frustum::Result<std::string> save_poster(const render::Renderer& renderer, const window::Frame& frame,
                                         const gl::FramebufferSize& size, int scale) {
    const int width_px = std::min(size.width_px * scale, render::kMaxPosterSidePx);
    const int height_px = std::min(size.height_px * scale, render::kMaxPosterSidePx);
    auto layout = frame.stereo ? render::stereo_poster_layout(renderer.functions(), width_px, height_px)
                               : render::poster_layout(renderer.functions(), width_px, height_px);
    if (!layout) {
        return layout.take_error();
    }
    render::RenderOptions options = frame.options;
    options.pass_end = nullptr; // the window's GPU timer marks only its own frames
    PosterJob job;
    job.effect = frame.effect;
    job.layout = *layout;
    job.stereo = frame.stereo;
    job.path = "frustum-window-" + std::to_string(scale) + "x.png";
    job.zlib_level = image::kStreamZlibLevel;
    auto written = write_poster(renderer, frame.cameras, options, job);
    if (!written) {
        return written.take_error();
    }
    return job.path;
}

// The settings with the mirror left where the scene has it now (placed at
// start-up or when its file was opened): the panel's changes do not move it.
Settings mirror_kept(Settings settings) {
    settings.mirror_place = {};
    return settings;
}

// Another scene file, opened as at start-up: load_scene() (the --scene
// and --camera of the settings) and a renderer uploading it, after the
// mirror is placed as the settings ask (plan::place_mirror(), which
// take_settings() then keeps). Nothing of the session changes here: on any
// error the old scene stays on screen and the message goes to the panel.
struct OpenedScene {
    LoadedScene loaded;
    std::optional<std::string> placed; // where the mirror went (plan::place_mirror())
    render::Renderer renderer;
};

std::variant<OpenedScene, std::string> open_scene(const WindowSession& s, const Settings& settings) {
    auto loaded = load_scene(settings);
    if (auto* failure = std::get_if<Failure>(&loaded)) {
        return failure->message;
    }
    LoadedScene& scene = std::get<LoadedScene>(loaded);
    // Placed where the new scene's camera sees it, as at start-up (docs/any-scene.md).
    auto cameras = plan::make_cameras(scene.scene, scene.camera_index, std::max(1, settings.width_px),
                                      std::max(1, settings.height_px));
    std::optional<std::string> placed =
        plan::place_mirror(scene.scene, settings.mirror_place, cameras ? &cameras->main.pair : nullptr);
    auto renderer = render::Renderer::create(*s.context, *s.fn, scene.scene);
    if (!renderer) {
        return renderer.error();
    }
    return OpenedScene{std::move(scene), std::move(placed), std::move(*renderer)};
}

// The opened scene replaces the session's: the old renderer (the old
// scene's buffers, textures and programs) is destroyed first.
void take_scene(WindowSession& s, OpenedScene opened, const Reporter& reporter) {
    if (opened.placed) {
        reporter.note(*opened.placed);
    }
    s.renderer.reset();
    s.renderer.emplace(std::move(opened.renderer));
    s.scene = std::move(opened.loaded.scene);
    s.camera_index = opened.loaded.camera_index;
}

// The key help (and why an effect was not drawn): frame.text as an ImGui
// window, "keys\taction" lines as a table, beside the panel when it is shown.
void draw_help(const std::vector<std::string>& lines, bool beside_panel) {
    // At most 70% of the width (the long lines wrap) and a smaller font in small windows.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float left_px = beside_panel ? kPanelWidthPx + 8.0f : 8.0f;
    const float width_px = std::max(120.0f, std::min(0.7f * display.x, display.x - left_px - 8.0f));
    ImGui::SetNextWindowPos(ImVec2(left_px, 8.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width_px, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.8f);
    ImGui::Begin("keys (H hides)", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar);
    ImGui::SetWindowFontScale(display.y < 600.0f ? 0.8f : 1.0f);
    bool table = false;
    for (const std::string& line : lines) {
        const std::size_t tab = line.find('\t');
        if (tab == std::string::npos) {
            if (table) {
                ImGui::EndTable();
                table = false;
            }
            ImGui::TextWrapped("%s", line.c_str());
            continue;
        }
        if (!table) {
            table = ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingStretchProp);
            ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed);
            ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
        }
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted(line.substr(0, tab).c_str());
        ImGui::TableSetColumnIndex(1);
        ImGui::TextWrapped("%s", line.substr(tab + 1).c_str());
    }
    if (table) {
        ImGui::EndTable();
    }
    ImGui::End();
}

// The mirror's screen rectangle (bottom-left pixels) as an outline, under the panel.
void outline(const plan::PixelRect& rect, int height_px) {
    const float top = static_cast<float>(height_px - rect.y - rect.height);
    ImGui::GetBackgroundDrawList()->AddRect(
        ImVec2(static_cast<float>(rect.x), top),
        ImVec2(static_cast<float>(rect.x + rect.width), top + static_cast<float>(rect.height)),
        IM_COL32(255, 220, 40, 255), 0.0f, 0, 2.0f);
}

// One window's frame loop: what it keeps between frames, and step(), one
// pass of it: input -> cameras -> controls -> mirror pose -> frame (the
// window::FrameStep the web page runs too) -> paint -> panel and help ->
// screenshot, swap, title.
class WindowLoop {
public:
    WindowLoop(const WindowRequest& request, const std::vector<std::string>& args, WindowSession& session,
               const std::function<void(std::string_view)>& note)
        : request_(request), s_(session), note_(note), reporter_{note, note},
          step_(session, initial_state(request, session)), state_(step_.state()), settings_(request),
          panel_(args, request),
          titled_effect_(state_.effect), size_(session.window->framebuffer_size()), shown_effect_(state_.effect),
          last_frame_(std::chrono::steady_clock::now()) {
        derive_from_scene();
        panel_.record_widgets(state_path_ != nullptr); // only FRUSTUM_WINDOW_STATE reads them
    }

    // One pass of the loop; `done` when the window is to close (Esc, or --frames reached).
    std::optional<Failure> step(bool& done);

    const WindowRun& run() const { return run_; }

private:
    // The panel's camera names: at start-up and for each scene file the panel loads.
    void derive_from_scene();
    // This pass's events (a --keys key, the panel's share taken out); false: nothing to draw (minimized).
    bool read_input(std::vector<gl::InputEvent>& events);
    // Paints the frame; a frame not drawn for this scene or camera keeps the previous effect and says why.
    std::optional<Failure> paint(window::Frame& frame, bool& painted, double& paint_ms);
    std::optional<Failure> draw_overlay(const window::Frame& frame, const std::vector<std::string>& help,
                                        double paint_ms);
    std::optional<Failure> take_panel_outcome(PanelOutcome outcome);
    std::optional<Failure> finish_frame(bool& done);
    void write_state() const;

    const WindowRequest& request_;
    WindowSession& s_;
    std::function<void(std::string_view)> note_;
    Reporter reporter_;
    std::vector<std::string> camera_names_; // --camera in the panel: a name, else the index
    std::optional<OpenedScene> opened_scene_; // another --scene the panel asked for, loaded by its check
    window::FrameStep step_;
    window::ViewerState& state_; // the step's
    Settings settings_; // what the panel last applied
    WindowPanel panel_;
    window::FrameClock clock_;
    std::optional<double> frame_ms_;
    plan::Effect titled_effect_;
    gl::FramebufferSize size_;
    WindowRun run_;
    plan::Effect shown_effect_;         // the last effect drawn
    std::optional<std::string> notice_; // why an effect was refused, in the overlay
    std::size_t keys_pressed_ = 0;      // of request.keys, one per pass of the loop
    bool screenshot_asked_ = false;     // the panel's button, saved at the next frame
    int screenshot_scale_ = 1;          // its size x the window's; above 1 a poster (save_poster())
    std::chrono::steady_clock::time_point last_frame_;
    // FRUSTUM_WINDOW_STATE=FILE (tests, docs/testing.md): after every frame
    // FILE holds "frame=N keys=K " + window::state_line() (K: --keys keys
    // pressed), replaced whole; FILE.log gets each line whose state differs
    // from the last one logged; FILE.widgets where the panel drew each of
    // its widgets in that frame (PanelWidgets::lines(), empty with the panel
    // hidden). Scripts wait for a state there, not for time, and click
    // widgets by name.
    const char* state_path_ = std::getenv("FRUSTUM_WINDOW_STATE");
    mutable std::string logged_state_;
};

void WindowLoop::write_state() const {
    const std::string state = window::state_line(state_);
    const std::string line =
        "frame=" + std::to_string(run_.frames_drawn) + " keys=" + std::to_string(keys_pressed_) + " " + state + "\n";
    const std::string path(state_path_);
    // A reader sees the old text or the new one, whole.
    const auto replace = [](const std::string& file, const std::string& text) {
        const std::string partial = file + ".partial";
        std::ofstream(partial, std::ios::trunc) << text;
        std::rename(partial.c_str(), file.c_str());
    };
    replace(path, line);
    replace(path + ".widgets", state_.show_panel ? panel_.widgets().lines() : std::string());
    if (state != logged_state_) {
        std::ofstream(path + ".log", std::ios::app) << line;
        logged_state_ = state;
    }
}

void WindowLoop::derive_from_scene() {
    camera_names_.clear();
    for (std::size_t i = 0; i < s_.scene.cameras.size(); ++i) {
        const std::string& name = s_.scene.cameras[i].name;
        camera_names_.push_back(name.empty() ? std::to_string(i) : name);
    }
}

bool WindowLoop::read_input(std::vector<gl::InputEvent>& events) {
    const bool minimized = size_.width_px < 1 || size_.height_px < 1;
    events = minimized ? s_.window->wait_events() : s_.window->poll_events();
    if (keys_pressed_ < request_.keys.size()) {
        events.emplace_back(request_.keys[keys_pressed_++]);
    }
    // The framebuffer size (not the window size) sets the frame, its aspect and the tiles.
    for (const gl::InputEvent& event : events) {
        if (const auto* resized = std::get_if<gl::FramebufferResized>(&event)) {
            size_ = {resized->width_px, resized->height_px};
        }
    }
    if (size_.width_px < 1 || size_.height_px < 1) {
        return false;
    }
    // The panel takes the mouse while the pointer is over it.
    events = s_.imgui->feed(std::move(events), state_.show_panel);
    return true;
}

std::optional<Failure> WindowLoop::paint(window::Frame& frame, bool& painted, double& paint_ms) {
    const auto paint_start = std::chrono::steady_clock::now();
    s_.timer->begin();
    s_.fragments->begin();
    frame.options.pass_end = [this](const char* pass) {
        s_.timer->mark(pass);
        s_.fragments->mark(pass);
    };
    // An explicit value this scene cannot take (resolve_effects()): only its effect is refused.
    frustum::Status status = frame.effect == plan::Effect::Curved && s_.effects.refused
                                 ? frustum::Status(frustum::Error{*s_.effects.refused})
                                 : s_.painter->paint(*s_.renderer, frame, size_.width_px, size_.height_px);
    s_.fragments->end();
    s_.timer->end();
    paint_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - paint_start).count();
    painted = status.ok();
    if (!painted) {
        // Not for this scene or camera: keep the previous effect (plain
        // when that one fails now too, then no inset), say why, go on.
        const std::string name(plan::to_string(frame.effect));
        if (frame.effect == plan::Effect::Plain && !frame.inset) {
            return runtime(status.error());
        }
        if (frame.effect != shown_effect_) {
            state_.effect = shown_effect_;
        } else if (frame.effect != plan::Effect::Plain) {
            state_.effect = plan::Effect::Plain;
        } else {
            state_.show_inset = false;
        }
        notice_ = (frame.effect == plan::Effect::Plain ? std::string("inset") : "effect " + name) +
                  " not drawn: " + status.error() + "; showing " + std::string(plan::to_string(state_.effect));
        note_(*notice_);
        return std::nullopt;
    }
    if (state_.effect != shown_effect_) {
        notice_.reset(); // a new effect was drawn: the old reason no longer applies
    }
    shown_effect_ = state_.effect;
    return std::nullopt;
}

std::optional<Failure> WindowLoop::draw_overlay(const window::Frame& frame, const std::vector<std::string>& help,
                                                double paint_ms) {
    // The panel and the help over the frame (nothing at all when both are hidden).
    if (!state_.show_panel && help.empty()) {
        return std::nullopt;
    }
    const auto now = std::chrono::steady_clock::now();
    s_.imgui->begin_frame(size_.width_px, size_.height_px, std::chrono::duration<double>(now - last_frame_).count());
    last_frame_ = now;
    if (!help.empty()) {
        draw_help(help, state_.show_panel);
    }
    if (state_.show_panel) {
        const window::LiveNumbers numbers = window::live_numbers(frame, s_.scene);
        PanelView view;
        view.numbers = &numbers;
        view.gpu_ms = s_.timer->last_ms();
        view.gpu_passes = s_.timer->last_passes();
        view.gpu_timer_available = s_.timer->available();
        view.fragment_passes = s_.fragments->last_passes();
        view.fragments_unavailable = s_.fragments->unavailable_reason();
        view.paint_cpu_ms = paint_ms;
        view.notice = notice_;
        view.mirror_size_m = step_.control_scene().mirror_size_m;
        view.scene_radius_m = window::bounds_radius(s_.scene.world_bounds);
        view.camera_names = camera_names_;
        view.check = [this](const Settings& next) -> std::optional<std::string> {
            if (auto samples = gl::choose_samples(*s_.fn, next.msaa_samples); !samples) {
                return "--msaa " + std::to_string(next.msaa_samples) + ": " + samples.error();
            }
            if (next.scene_path != settings_.scene_path) {
                auto opened = open_scene(s_, next);
                if (auto* error = std::get_if<std::string>(&opened)) {
                    return *error;
                }
                opened_scene_.emplace(std::move(std::get<OpenedScene>(opened)));
            }
            return std::nullopt;
        };
        PanelOutcome outcome = panel_.draw(state_, view);
        const bool mirror_shown = frame.effect == plan::Effect::Mirror || frame.effect == plan::Effect::Curved;
        if (numbers.mirror_rect && mirror_shown && !frame.stereo) {
            outline(*numbers.mirror_rect, size_.height_px);
        }
        if (auto failure = take_panel_outcome(std::move(outcome))) {
            return failure;
        }
    }
    if (auto drawn = s_.imgui->end_frame(); !drawn) {
        return runtime(drawn.error());
    }
    return std::nullopt;
}

std::optional<Failure> WindowLoop::take_panel_outcome(PanelOutcome outcome) {
    if (outcome.settings && opened_scene_) {
        // The new scene: its camera framed anew, the mirror and the facing mirrors where it puts them.
        take_scene(s_, std::move(*opened_scene_), reporter_);
        opened_scene_.reset();
        derive_from_scene();
        step_.scene_replaced();
    }
    if (outcome.settings) {
        if (outcome.settings->camera != settings_.camera) {
            // Another scene camera: found as at start-up (plan::find_camera), the orbit dropped.
            auto index = plan::find_camera(s_.scene, outcome.settings->camera);
            if (!index) {
                return runtime(index.error());
            }
            s_.camera_index = *index;
            step_.camera_changed();
        }
        settings_ = std::move(*outcome.settings);
        take_settings(mirror_kept(settings_), s_, state_);
        step_.reset_cameras(); // --stereo may have changed the eye's width
        notice_.reset();
    }
    screenshot_asked_ = screenshot_asked_ || outcome.screenshot;
    if (outcome.screenshot) {
        screenshot_scale_ = outcome.screenshot_scale;
    }
    return std::nullopt;
}

std::optional<Failure> WindowLoop::finish_frame(bool& done) {
    ++run_.frames_drawn;
    const bool last = request_.frames && run_.frames_drawn >= *request_.frames;
    if ((last && request_.screenshot) || (screenshot_asked_ && !request_.frames)) {
        const std::string path = request_.screenshot.value_or(kPanelScreenshot);
        if (auto saved = save_screenshot(*s_.fn, size_, path); !saved) {
            return runtime(saved.error());
        }
        if (!last) {
            note_("screenshot: " + path);
        }
        run_.written_paths.push_back(path);
        screenshot_asked_ = false;
    }
    s_.window->swap_buffers();
    if (state_path_ != nullptr && *state_path_ != '\0') {
        write_state();
    }
    if (auto mean = clock_.tick(std::chrono::steady_clock::now()); mean || titled_effect_ != state_.effect) {
        frame_ms_ = mean ? mean : frame_ms_;
        titled_effect_ = state_.effect;
        s_.window->set_title(window::window_title(state_.effect, frame_ms_));
    }
    done = last;
    return std::nullopt;
}

std::optional<Failure> WindowLoop::step(bool& done) {
    done = s_.window->should_close();
    std::vector<gl::InputEvent> events;
    if (done || !read_input(events)) {
        return std::nullopt;
    }
    // Stereo: cameras, frame and options are one eye's, half the width (window::FrameStep).
    auto stepped = step_.step(events, size_.width_px, size_.height_px);
    if (!stepped) {
        return runtime(stepped.error());
    }
    if (!*stepped) { // the input asked to quit
        s_.window->request_close();
        done = true;
        return std::nullopt;
    }
    std::optional<window::Frame>& frame = *stepped;
    if (notice_ && !state_.show_panel) {
        frame->text.insert(frame->text.begin(), *notice_);
    }
    // The help goes into an ImGui window (draw_overlay()), not the painter's text panel.
    const std::vector<std::string> help = std::move(frame->text);
    frame->text.clear();
    bool painted = false;
    double paint_ms = 0.0;
    if (auto failure = paint(*frame, painted, paint_ms)) {
        return failure;
    }
    if (!painted) {
        return std::nullopt;
    }
    if (auto failure = draw_overlay(*frame, help, paint_ms)) {
        return failure;
    }
    if (screenshot_asked_ && screenshot_scale_ > 1 && !request_.frames) {
        // A poster of this frame's view; a failure is a note, the window goes on.
        auto saved = save_poster(*s_.renderer, *frame, size_, screenshot_scale_);
        note_(saved ? "screenshot: " + *saved : "screenshot: " + saved.error());
        if (saved) {
            run_.written_paths.push_back(*saved);
        }
        screenshot_asked_ = false;
    }
    return finish_frame(done);
}

} // namespace

std::variant<WindowRun, Failure> run_window(const WindowRequest& request, const std::vector<std::string>& args,
                                            const std::function<void(std::string_view)>& note) {
    auto opened = open_session(request, note);
    if (auto* failure = std::get_if<Failure>(&opened)) {
        return *failure;
    }
    WindowLoop loop(request, args, *std::get<std::unique_ptr<WindowSession>>(opened), note);
    for (bool done = false; !done;) {
        if (auto failure = loop.step(done)) {
            return *failure;
        }
    }
    return loop.run();
}

} // namespace demo
