// The window's control panel (Dear ImGui; key P shows or hides it): one
// widget per row of the option table that window accepts and that names a
// PanelControl (demo/effect_options.hpp), plus its flags as checkboxes, the
// mirror's placement, the scene file (a text field, a load button and the
// files beside it), a screenshot button, and the live numbers of the
// frame. A changed widget edits the window's command line
// (demo/panel_command_line.hpp), which is re-parsed by the same code as at
// start-up: a value the row refuses shows the row's message in the panel
// and changes nothing. Draws between window::ImGuiLayer::begin_frame() and
// end_frame().
#pragma once

#include "demo/panel_command_line.hpp"
#include "demo/panel_widgets.hpp"

#include <window/controls.hpp>
#include <window/fragment_counter.hpp>
#include <window/gpu_timer.hpp>
#include <window/live_numbers.hpp>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace demo {

// The panel covers the window's left kPanelWidthPx screen units, full height.
inline constexpr float kPanelWidthPx = 330.0f;

struct PanelView {
    const window::LiveNumbers* numbers = nullptr;
    std::optional<double> gpu_ms;  // timer query of the last frame, when the context has one
    std::vector<window::GpuTimer::PassTime> gpu_passes; // that frame's passes (timestamp queries)
    double paint_cpu_ms = 0.0;     // CPU wall time of the frame's GL calls
    bool gpu_timer_available = false;
    std::vector<window::FragmentCounter::PassSamples> fragment_passes; // samples passed per pass (desktop GL)
    std::optional<std::string> fragments_unavailable; // why there are none (OpenGL ES)
    std::optional<std::string> notice; // why an effect was not drawn
    float mirror_size_m = 0.0f; // window::ControlScene's; 0: no mirror sliders
    float scene_radius_m = 1.0f; // the recursion mirrors' push sliders span half of it either way
    std::vector<std::string> camera_names; // the scene's cameras, for --camera (index order)
    // What only the running window can check (e.g. --msaa against the
    // context's GL_MAX_SAMPLES, or that another --scene loads): a message
    // refuses the parsed settings.
    std::function<std::optional<std::string>(const Settings&)> check;
};

struct PanelOutcome {
    std::optional<Settings> settings; // a control changed and the command line parses
    bool screenshot = false;          // the screenshot button
    int screenshot_scale = 1;         // its size: 1, 2, 4 or 8 x the window's (above 1, a poster)
};

class WindowPanel {
public:
    // args: the window's command line (args[0] "window"); settings: its parse.
    WindowPanel(std::vector<std::string> args, Settings settings);

    // Rows the keys change (effect, tiles, mirror, lens power, recursion
    // depth) follow `state` first; the mirror sliders edit state.mirror.
    PanelOutcome draw(window::ViewerState& state, const PanelView& view);

    const PanelCommandLine& command_line() const { return line_; }
    // Where draw() put its widgets (empty until it has drawn, and unless
    // recorded: off by default).
    const PanelWidgets& widgets() const { return widgets_; }
    void record_widgets(bool on) { widgets_.record(on); }

private:
    void follow(const window::ViewerState& state);
    void messages(const PanelView& view) const;
    bool option_rows(plan::Effect shown, const PanelView& view);
    std::optional<Settings> take_edit(const PanelView& view);
    void screenshot(PanelOutcome& outcome);
    bool row_widget(const Option& option, const PanelView& view);
    bool scene_file();
    void numbers(const PanelView& view) const;
    void geometry(const window::LiveNumbers& numbers) const;

    PanelCommandLine line_;
    PanelCommandLine accepted_; // the last command line the window took
    Settings current_;
    std::optional<std::string> error_;
    int screenshot_scale_index_ = 0; // the screenshot size: 1 << index times the window's
    std::array<char, 1024> scene_field_{}; // the scene file's text field
    bool followed_ = false;
    PanelWidgets widgets_;
};

} // namespace demo
