// Where the window's panel drew its widgets in the last frame, by name, in
// window pixels (ImGui's coordinates, those xdotool clicks at). With
// FRUSTUM_WINDOW_STATE=FILE the window writes them to FILE.widgets after
// every frame, so the panel's test scripts click a widget by its name
// instead of at a position worked out from ImGui's font and style
// (tests/window/panel_steps.sh, docs/testing.md).
//
// Names: an option row is its option ("--lens-power"; a slider's
// rectangle is the span its grab's centre moves along, so a click a
// fraction t along a linear slider sets low + t (high - low)); a list's
// entry, shown while it is open, is "LIST=ENTRY" ("--effect=lens",
// "beside it=box.gltf"); other widgets go by their label ("load",
// "screenshot"). Only widgets wholly inside their window are listed: one
// scrolled out of the panel is not there until it is scrolled in.
#pragma once

#include <string>
#include <vector>

namespace demo {

struct PanelWidget {
    std::string name;
    float x0_px = 0.0f, y0_px = 0.0f, x1_px = 0.0f, y1_px = 0.0f;
};

class PanelWidgets {
public:
    // Off (the default), nothing is recorded: the calls below return at once.
    void record(bool on) { on_ = on; }
    void clear() { widgets_.clear(); }
    // The last ImGui item, whole (a button, a checkbox, a list entry).
    void item(const std::string& name);
    // The framed widget about to be drawn at the cursor (a list, a text
    // field): its frame, ImGui::CalcItemWidth() by ImGui::GetFrameHeight(),
    // without the label. Taken before the widget, as a list's popup opened
    // inside it replaces ImGui's last item.
    void next_frame(const std::string& name);
    // The one-component slider over [low, high] about to be drawn at the
    // cursor: the span its grab's centre moves along (ImGui's
    // SliderBehavior: 2 px padding, the grab GrabMinSize wide, or a step's
    // width for whole numbers).
    void next_slider(const std::string& name, bool whole, float low, float high);

    const std::vector<PanelWidget>& all() const { return widgets_; }
    // "x0 y0 x1 y1 name" per widget, one per line, in drawing order.
    std::string lines() const;

private:
    void add(const std::string& name, float x0_px, float y0_px, float x1_px, float y1_px);
    std::vector<PanelWidget> widgets_;
    bool on_ = false;
};

} // namespace demo
