#include "demo/window_panel.hpp"

#include "demo/scene_files.hpp"

#include <plan/number_text.hpp>

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace demo {
namespace {

constexpr float kMirrorTravel = 2.0f; // the slide and push sliders: this many mirror sizes either way

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t at = text.find(separator, start);
        parts.push_back(text.substr(start, at - start));
        if (at == std::string::npos) {
            return parts;
        }
        start = at + 1;
    }
}

std::string join(const float* values, int count, const PanelControl& control) {
    std::string text;
    for (int i = 0; i < count; ++i) {
        text += (i ? std::string(1, control.separator) : std::string()) +
                (control.whole ? std::to_string(static_cast<int>(std::lround(values[i])))
                               : plan::number_text(values[i]));
    }
    return text;
}

// The effect a row belongs to: its help line starts with "<effect> effect"
// (effect_options.cpp's convention); empty for the others.
std::optional<plan::Effect> row_effect(const Option& option) {
    for (const plan::Effect effect : plan::kAllEffects) {
        const std::string prefix = std::string(plan::to_string(effect)) + " effect";
        if (option.help.compare(0, prefix.size(), prefix) == 0) {
            return effect;
        }
    }
    return std::nullopt;
}

void tooltip(const std::string& help) {
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s", help.c_str());
    }
}

// Puts `text` into a text field's buffer (cut to fit, always terminated).
void fill(std::array<char, 1024>& field, const std::string& text) {
    const std::size_t n = std::min(text.size(), field.size() - 1);
    std::copy(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(n), field.begin());
    field[n] = '\0';
}

} // namespace

WindowPanel::WindowPanel(std::vector<std::string> args, Settings settings)
    : line_(std::move(args)), accepted_(line_), current_(std::move(settings)) {
    fill(scene_field_, current_.scene_path);
}

// The scene file: the path typed (Enter or the load button) or one of the
// files beside the current one goes on the command line as --scene,
// without the options that name parts of the old scene (--camera,
// --mirror-plane, --mirror-rect: the new one's are derived). True when
// the command line changed; the window loads it when it is checked.
bool WindowPanel::scene_file() {
    if (!ImGui::CollapsingHeader("scene file", ImGuiTreeNodeFlags_DefaultOpen)) {
        return false;
    }
    ImGui::PushID("scene file");
    ImGui::PushItemWidth(-60.0f);
    widgets_.next_frame("scene path");
    bool load = ImGui::InputText("##path", scene_field_.data(), scene_field_.size(),
                                 ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
    ImGui::PopItemWidth();
    tooltip("--scene: a glTF 2.0 file (.gltf or .glb); a click selects it all, Enter or load opens it");
    ImGui::SameLine();
    load = ImGui::Button("load") || load;
    widgets_.item("load");
    widgets_.next_frame("beside it");
    if (ImGui::BeginCombo("beside it", std::filesystem::path(current_.scene_path).filename().string().c_str())) {
        const std::vector<std::string> files = scene_files_beside(current_.scene_path); // read while open
        for (std::size_t i = 0; i < files.size(); ++i) {
            ImGui::PushID(static_cast<int>(i));
            const std::string name = std::filesystem::path(files[i]).filename().string();
            if (ImGui::Selectable(name.c_str(), files[i] == current_.scene_path)) {
                fill(scene_field_, files[i]);
                load = true;
            }
            widgets_.item("beside it=" + name);
            ImGui::PopID();
        }
        ImGui::EndCombo();
    }
    tooltip("the .gltf and .glb files in the scene's folder and the folders next to it");
    ImGui::PopID();
    if (load) {
        line_.set("--scene", scene_field_.data());
        for (const char* name : {"--camera", "--mirror-plane", "--mirror-rect"}) {
            line_.remove(name);
        }
    }
    return load;
}

void WindowPanel::follow(const window::ViewerState& state) {
    // The first time, every followed row goes on the command line, so its widget shows the value.
    const bool first = !followed_;
    const auto keep = [&](const std::string& name, const std::string& value) {
        line_.set(name, value);
        accepted_.set(name, value); // the keys' changes are taken at once
    };
    followed_ = true;
    if (first || current_.effects.empty() || state.effect != current_.effects.front()) {
        keep("--effect", std::string(plan::to_string(state.effect)));
        current_.effects = {state.effect};
    }
    if (first || state.tile_columns != current_.tile_columns || state.tile_rows != current_.tile_rows) {
        keep("--tiles", std::to_string(state.tile_columns) + "x" + std::to_string(state.tile_rows));
        current_.tile_columns = state.tile_columns;
        current_.tile_rows = state.tile_rows;
    }
    if (first || state.mirror_method != current_.mirror_method) {
        keep("--mirror", std::string(plan::to_string(state.mirror_method)));
        current_.mirror_method = state.mirror_method;
    }
    if (first || state.lens_power != current_.lens_power) {
        keep("--lens-power", plan::number_text(state.lens_power));
        current_.lens_power = state.lens_power;
    }
    if (first || state.recursion_depth != current_.recursion_depth) {
        keep("--recursion-depth", std::to_string(state.recursion_depth));
        current_.recursion_depth = state.recursion_depth;
    }
}

// One row's widget; true when it changed the command line.
bool WindowPanel::row_widget(const Option& option, const PanelView& view) {
    const PanelControl& control = option.control;
    const std::optional<std::string> given = line_.value(option.name);
    const char* label = option.name.c_str();
    if (!option.value) {
        bool on = given.has_value();
        const bool changed = ImGui::Checkbox(label, &on);
        widgets_.item(option.name);
        tooltip(option.help);
        if (changed) {
            on ? line_.set(option.name, "") : line_.remove(option.name);
        }
        return changed;
    }
    if (control.kind == PanelControl::Kind::Choice || control.kind == PanelControl::Kind::SceneCamera) {
        const std::vector<std::string> choices =
            control.kind == PanelControl::Kind::Choice ? split(control.choices, '|') : view.camera_names;
        const std::string shown = given ? *given : "(default)";
        bool changed = false;
        widgets_.next_frame(option.name);
        if (ImGui::BeginCombo(label, shown.c_str())) {
            for (const std::string& choice : choices) {
                if (ImGui::Selectable(choice.c_str(), given && *given == choice)) {
                    line_.set(option.name, choice);
                    changed = true;
                }
                widgets_.item(option.name + "=" + choice);
            }
            ImGui::EndCombo();
        }
        tooltip(option.help);
        return changed;
    }
    // A slider row: unset rows (derived from the scene) start at the row's example when set.
    ImGui::PushID(label);
    bool set = given.has_value();
    bool changed = ImGui::Checkbox("##set", &set);
    widgets_.item(option.name + " set");
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("set %s (unticked: the default, derived from the scene)", label);
    }
    ImGui::SameLine();
    if (changed && !set) {
        line_.remove(option.name);
    } else if (changed && set) {
        line_.set(option.name, option.example ? option.example : "");
    }
    ImGui::PopID();
    const std::optional<std::string> text = line_.value(option.name);
    if (!text) {
        ImGui::TextDisabled("%s (default)", label);
        tooltip(option.help);
        return changed;
    }
    const std::vector<std::string> parts = split(*text, control.separator);
    std::array<float, 4> v{};
    const int count = std::min(control.components, 4);
    for (int i = 0; i < count && i < static_cast<int>(parts.size()); ++i) {
        v[i] = std::strtof(parts[i].c_str(), nullptr);
    }
    const ImGuiSliderFlags flags = control.logarithmic ? ImGuiSliderFlags_Logarithmic : 0;
    if (count == 1) {
        widgets_.next_slider(option.name, control.whole, control.low, control.high);
    } else {
        widgets_.next_frame(option.name);
    }
    bool moved = false;
    if (control.whole) {
        std::array<int, 4> n{};
        for (int i = 0; i < count; ++i) {
            n[i] = static_cast<int>(std::lround(v[i]));
        }
        const int low = static_cast<int>(control.low), high = static_cast<int>(control.high);
        moved = ImGui::SliderScalarN(label, ImGuiDataType_S32, n.data(), count, &low, &high, "%d", flags);
        for (int i = 0; i < count; ++i) {
            v[i] = static_cast<float>(n[i]);
        }
    } else {
        const float low = control.low, high = control.high;
        moved = ImGui::SliderScalarN(label, ImGuiDataType_Float, v.data(), count, &low, &high, "%.3g", flags);
    }
    tooltip(option.help);
    if (moved) {
        line_.set(option.name, join(v.data(), count, control));
    }
    return changed || moved;
}

namespace {

// The panel's window: the left kPanelWidthPx, full height, fixed; its
// widgets' width (PushItemWidth) is popped in WindowPanel::draw().
void begin_panel_window() {
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidthPx, ImGui::GetIO().DisplaySize.y), ImGuiCond_Always);
    ImGui::Begin("frustum-demo window (P hides)", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(-125.0f);
}

// The recursion effect's two facing mirrors (keys Z X, C V): push and turn of each.
void facing_mirrors(window::ViewerState& state, const PanelView& view, PanelWidgets& widgets) {
    if (!(state.effect == plan::Effect::Recursion && state.link_moves.size() >= 2 &&
          ImGui::CollapsingHeader("facing mirrors (Z X, C V)", ImGuiTreeNodeFlags_DefaultOpen))) {
        return;
    }
    const float reach_m = 0.5f * view.scene_radius_m;
    const char* sides[] = {"left", "right"};
    for (int i = 0; i < 2; ++i) {
        plan::LinkMove& move = state.link_moves[static_cast<std::size_t>(i)];
        const std::string push = std::string(sides[i]) + " in m", turn = std::string(sides[i]) + " turn";
        ImGui::PushID(i);
        widgets.next_slider(push, false, -reach_m, reach_m);
        ImGui::SliderFloat(push.c_str(), &move.push_m, -reach_m, reach_m, "%.3g");
        widgets.next_slider(turn, false, -60.0f, 60.0f);
        ImGui::SliderAngle(turn.c_str(), &move.turn_rad, -60.0f, 60.0f);
        ImGui::PopID();
    }
}

// The mirror's turn, tilt, slide and push (when the scene has one), and M's reset.
void mirror_placement(window::ViewerState& state, const PanelView& view, PanelWidgets& widgets) {
    const float travel_m = kMirrorTravel * view.mirror_size_m;
    if (!(view.mirror_size_m > 0.0f && ImGui::CollapsingHeader("mirror placement", ImGuiTreeNodeFlags_DefaultOpen))) {
        return;
    }
    widgets.next_slider("turn", false, -180.0f, 180.0f);
    ImGui::SliderAngle("turn", &state.mirror.turn_rad, -180.0f, 180.0f);
    widgets.next_slider("tilt", false, -85.0f, 85.0f);
    ImGui::SliderAngle("tilt", &state.mirror.tilt_rad, -85.0f, 85.0f);
    widgets.next_slider("slide m", false, -travel_m, travel_m);
    ImGui::SliderFloat("slide m", &state.mirror.slide_m, -travel_m, travel_m, "%.3g");
    widgets.next_slider("push m", false, -travel_m, travel_m);
    ImGui::SliderFloat("push m", &state.mirror.push_m, -travel_m, travel_m, "%.3g");
    if (ImGui::Button("mirror back (M)")) {
        state.mirror = {};
    }
    widgets.item("mirror back (M)");
}

} // namespace

// A refused value (from the last edit) and why an effect was not drawn, on top.
void WindowPanel::messages(const PanelView& view) const {
    if (error_) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("not applied: %s", error_->c_str());
        ImGui::PopStyleColor();
    }
    if (view.notice) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s", view.notice->c_str());
        ImGui::PopStyleColor();
    }
}

// The option rows: those of no one effect (--effect, --msaa, fog, stereo),
// then those of the effect shown, then the other effects' (folded). True
// when a row changed the command line.
bool WindowPanel::option_rows(plan::Effect shown, const PanelView& view) {
    bool edited = false;
    const auto rows = [&](auto&& take) {
        for (const Option& option : options()) {
            const bool panel_row = (option.commands & kWindow) &&
                                   (option.control.kind != PanelControl::Kind::None ||
                                    (option.effect_row && !option.value));
            if (panel_row && take(row_effect(option))) {
                edited = row_widget(option, view) || edited;
            }
        }
    };
    ImGui::TextDisabled("hover a name for its --help line");
    rows([](std::optional<plan::Effect> effect) { return !effect; });
    const std::string own = std::string(plan::to_string(shown)) + " effect";
    ImGui::Separator();
    ImGui::TextUnformatted(own.c_str());
    rows([&](std::optional<plan::Effect> effect) { return effect == shown; });
    if (ImGui::CollapsingHeader("the other effects' options")) {
        rows([&](std::optional<plan::Effect> effect) { return effect && effect != shown; });
    }
    return edited;
}

// After an edit: the command line parsed and checked. The settings when
// the window takes them; otherwise empty, with the message shown next
// frame (a refused line goes back to the last one taken).
std::optional<Settings> WindowPanel::take_edit(const PanelView& view) {
    auto parsed = line_.parse();
    auto* settings = std::get_if<Settings>(&parsed);
    const std::optional<std::string> refused = settings && view.check ? view.check(*settings) : std::nullopt;
    if (settings && !refused) {
        error_.reset();
        current_ = *settings;
        accepted_ = line_;
        return *settings;
    }
    if (refused) {
        error_ = *refused;
        line_ = accepted_; // the window keeps what it shows
    } else if (auto* failure = std::get_if<Failure>(&parsed)) {
        error_ = failure->message;
    }
    return std::nullopt;
}

// The screenshot size and button. Above 1x, a poster of the current view
// (render::render_poster(), streamed to PNG).
void WindowPanel::screenshot(PanelOutcome& outcome) {
    const char* scales[] = {"1x", "2x", "4x", "8x"};
    widgets_.next_frame("screenshot size");
    if (ImGui::BeginCombo("screenshot size", scales[screenshot_scale_index_])) {
        for (int i = 0; i < 4; ++i) {
            if (ImGui::Selectable(scales[i], i == screenshot_scale_index_)) {
                screenshot_scale_index_ = i;
            }
            widgets_.item(std::string("screenshot size=") + scales[i]);
        }
        ImGui::EndCombo();
    }
    const bool clicked = ImGui::Button("screenshot");
    widgets_.item("screenshot");
    if (clicked) {
        outcome.screenshot = true;
        outcome.screenshot_scale = 1 << screenshot_scale_index_;
    }
}

PanelOutcome WindowPanel::draw(window::ViewerState& state, const PanelView& view) {
    follow(state);
    PanelOutcome outcome;
    widgets_.clear();
    begin_panel_window();
    messages(view);
    bool edited = option_rows(state.effect, view);
    edited = scene_file() || edited;
    if (edited) {
        outcome.settings = take_edit(view);
    }
    facing_mirrors(state, view, widgets_);
    numbers(view);
    mirror_placement(state, view, widgets_);
    screenshot(outcome);
    ImGui::TextWrapped("%s", line_.text().c_str());
    ImGui::PopItemWidth();
    ImGui::End();
    return outcome;
}

// The pair's planes (normalized, inward: a x + b y + c z + d >= 0 inside)
// and key points (world; "at infinity" gives the direction), §3.
void WindowPanel::geometry(const window::LiveNumbers& n) const {
    if (!ImGui::TreeNode("planes and key points (paper section 3)")) {
        return;
    }
    const char* plane_names[6] = {"left", "right", "bottom", "top", "near", "far"};
    const auto planes = n.planes.as_array();
    for (std::size_t i = 0; i < planes.size(); ++i) {
        if (!planes[i]) {
            ImGui::Text("  %-6s at infinity", plane_names[i]);
            continue;
        }
        const glm::vec4& p = planes[i]->abcd;
        ImGui::Text("  %-6s %8.4f %8.4f %8.4f %9.4f", plane_names[i], static_cast<double>(p.x), static_cast<double>(p.y),
                    static_cast<double>(p.z), static_cast<double>(p.w));
    }
    const auto point = [](const std::string& name, const glm::vec4& p) {
        ImGui::Text("  %-4s %9.4f %9.4f %9.4f%s", name.c_str(), static_cast<double>(p.x), static_cast<double>(p.y),
                    static_cast<double>(p.z), p.w == 0.0f ? "  (direction, at infinity)" : "");
    };
    point("O", n.points.eye);
    point("D", n.points.center);
    for (std::size_t i = 0; i < n.points.corners.size(); ++i) {
        point("C" + std::to_string(i + 1), n.points.corners[i]);
    }
    point("O1", n.points.vanishing_y);
    point("O2", n.points.vanishing_x);
    ImGui::TreePop();
}

namespace {

// Per pass: GPU ms (timestamps) and samples passed (occlusion queries), joined by pass name.
void pass_table(const PanelView& view) {
    struct Row {
        std::string pass;
        std::optional<double> gpu_ms;
        std::optional<std::uint64_t> samples;
    };
    std::vector<Row> rows;
    for (const window::GpuTimer::PassTime& pass : view.gpu_passes) {
        rows.push_back({pass.pass, pass.gpu_ms, std::nullopt});
    }
    for (const window::FragmentCounter::PassSamples& pass : view.fragment_passes) {
        const auto same = std::find_if(rows.begin(), rows.end(), [&](const Row& row) { return row.pass == pass.pass; });
        if (same != rows.end()) {
            same->samples = pass.samples;
        } else {
            rows.push_back({pass.pass, std::nullopt, pass.samples});
        }
    }
    if (rows.empty() || !ImGui::BeginTable("passes", 3, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg)) {
        return;
    }
    ImGui::TableSetupColumn("pass");
    ImGui::TableSetupColumn("GPU ms");
    ImGui::TableSetupColumn("samples");
    ImGui::TableHeadersRow();
    for (const Row& row : rows) {
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted(row.pass.c_str());
        ImGui::TableSetColumnIndex(1);
        row.gpu_ms ? ImGui::Text("%.3f", *row.gpu_ms) : ImGui::TextDisabled("-");
        ImGui::TableSetColumnIndex(2);
        row.samples ? ImGui::Text("%llu", static_cast<unsigned long long>(*row.samples)) : ImGui::TextDisabled("-");
    }
    ImGui::EndTable();
}

} // namespace

void WindowPanel::numbers(const PanelView& view) const {
    if (!view.numbers || !ImGui::CollapsingHeader("numbers", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    const window::LiveNumbers& n = *view.numbers;
    const auto matrix = [](const char* name, const glm::mat4& m) {
        ImGui::Text("%s", name);
        for (int r = 0; r < 4; ++r) {
            ImGui::Text("  %9.4f %9.4f %9.4f %9.4f", static_cast<double>(m[0][r]), static_cast<double>(m[1][r]),
                        static_cast<double>(m[2][r]), static_cast<double>(m[3][r]));
        }
    };
    matrix("camera M (clip = M world)", n.pair.matrix());
    matrix("its inverse M^-1 (analytic)", n.pair.inverse());
    ImGui::Text("|M M^-1 - I| = %.3g (largest entry)", n.residual);
    geometry(n);
    if (n.mirror_rect) {
        ImGui::TextWrapped("mirror rectangle: %dx%d px at %d,%d from the bottom left (outlined in the mirror effects)",
                           n.mirror_rect->width, n.mirror_rect->height, n.mirror_rect->x, n.mirror_rect->y);
    }
    for (const window::PassTiming& pass : n.passes) {
        ImGui::TextWrapped("%s: %.1f us CPU", pass.pass.c_str(), pass.cpu_us);
        ImGui::TextDisabled("  %s", pass.result.c_str());
    }
    if (view.gpu_ms) {
        ImGui::Text("frame GPU time: %.3f ms (timer query)", *view.gpu_ms);
    } else {
        ImGui::Text("frame: %.3f ms CPU wall time (%s)", view.paint_cpu_ms,
                    view.gpu_timer_available ? "timer result pending" : "no GPU timer query in this context");
    }
    if (view.fragments_unavailable) {
        ImGui::TextWrapped("fragments: %s", view.fragments_unavailable->c_str());
    }
    pass_table(view);
}

} // namespace demo
