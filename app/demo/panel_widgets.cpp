#include "demo/panel_widgets.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace demo {

void PanelWidgets::add(const std::string& name, float x0_px, float y0_px, float x1_px, float y1_px) {
    const ImVec2 window_min = ImGui::GetWindowPos(), window_size = ImGui::GetWindowSize();
    const bool inside = x0_px >= window_min.x && y0_px >= window_min.y && x1_px <= window_min.x + window_size.x &&
                        y1_px <= window_min.y + window_size.y;
    if (inside) {
        widgets_.push_back({name, x0_px, y0_px, x1_px, y1_px});
    }
}

void PanelWidgets::item(const std::string& name) {
    if (!on_) {
        return;
    }
    const ImVec2 top = ImGui::GetItemRectMin(), bottom = ImGui::GetItemRectMax();
    add(name, top.x, top.y, bottom.x, bottom.y);
}

void PanelWidgets::next_frame(const std::string& name) {
    if (!on_) {
        return;
    }
    const ImVec2 top = ImGui::GetCursorScreenPos();
    add(name, top.x, top.y, top.x + ImGui::CalcItemWidth(), top.y + ImGui::GetFrameHeight());
}

void PanelWidgets::next_slider(const std::string& name, bool whole, float low, float high) {
    if (!on_) {
        return;
    }
    constexpr float kGrabPaddingPx = 2.0f; // imgui_widgets.cpp, SliderBehaviorT
    const ImVec2 top = ImGui::GetCursorScreenPos();
    const float slider_px = ImGui::CalcItemWidth() - 2.0f * kGrabPaddingPx;
    float grab_px = ImGui::GetStyle().GrabMinSize;
    if (whole) {
        grab_px = std::max(slider_px / (std::abs(high - low) + 1.0f), grab_px);
    }
    grab_px = std::min(grab_px, slider_px);
    const float start_px = top.x + kGrabPaddingPx + 0.5f * grab_px;
    add(name, start_px, top.y, start_px + slider_px - grab_px, top.y + ImGui::GetFrameHeight());
}

std::string PanelWidgets::lines() const {
    std::string text;
    char numbers[96];
    for (const PanelWidget& w : widgets_) {
        std::snprintf(numbers, sizeof numbers, "%.1f %.1f %.1f %.1f ", static_cast<double>(w.x0_px),
                      static_cast<double>(w.y0_px), static_cast<double>(w.x1_px), static_cast<double>(w.y1_px));
        text += numbers + w.name + "\n";
    }
    return text;
}

} // namespace demo
