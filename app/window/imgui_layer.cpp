#include "window/imgui_layer.hpp"

#include <imgui.h>

#include <type_traits>
#include <utility>
#include <variant>

namespace window {

ImGuiLayer::ImGuiLayer(ImGuiContext* context, ImGuiPainter painter)
    : context_(context), painter_(std::move(painter)) {}

ImGuiLayer::~ImGuiLayer() { ImGui::DestroyContext(context_); }

frustum::Result<std::unique_ptr<ImGuiLayer>> ImGuiLayer::create(const gl::Functions& fn) {
    ImGuiContext* context = ImGui::CreateContext();
    ImGui::SetCurrentContext(context);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini: a run does not depend on the last one
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    auto painter = ImGuiPainter::create(fn);
    if (!painter) {
        ImGui::DestroyContext(context);
        return painter.take_error();
    }
    return std::unique_ptr<ImGuiLayer>(new ImGuiLayer(context, std::move(*painter)));
}

void ImGuiLayer::apply(const gl::InputEvent& event) {
    ImGuiIO& io = ImGui::GetIO();
    std::visit(
        [&](const auto& e) {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, gl::CursorMoved>) {
                io.MousePos = ImVec2(static_cast<float>(e.x), static_cast<float>(e.y));
            } else if constexpr (std::is_same_v<E, gl::MouseButtonChanged>) {
                const int button = e.button == gl::MouseButton::Left ? 0 : e.button == gl::MouseButton::Right ? 1 : 2;
                io.MouseDown[button] = e.pressed;
            } else if constexpr (std::is_same_v<E, gl::Scrolled>) {
                io.MouseWheelH += static_cast<float>(e.dx);
                io.MouseWheel += static_cast<float>(e.dy);
            }
        },
        event);
}

std::vector<gl::InputEvent> ImGuiLayer::feed(std::vector<gl::InputEvent> events, bool shown) {
    if (!shown) {
        waiting_.clear();
        ImGuiIO& io = ImGui::GetIO();
        for (bool& down : io.MouseDown) {
            down = false;
        }
        return events;
    }
    const ImGuiIO& io = ImGui::GetIO();
    const bool captured = io.WantCaptureMouse;
    std::vector<gl::InputEvent> passed;
    std::vector<gl::InputEvent> mouse = std::move(waiting_);
    waiting_.clear();
    for (gl::InputEvent& event : events) {
        const bool is_mouse = std::holds_alternative<gl::CursorMoved>(event) ||
                              std::holds_alternative<gl::MouseButtonChanged>(event) ||
                              std::holds_alternative<gl::Scrolled>(event);
        if (is_mouse) {
            mouse.push_back(event);
        }
        if (!is_mouse || !captured) {
            passed.push_back(std::move(event));
        }
    }
    bool button_changed = false;
    for (std::size_t i = 0; i < mouse.size(); ++i) {
        const bool is_button = std::holds_alternative<gl::MouseButtonChanged>(mouse[i]);
        if (is_button && button_changed) {
            waiting_.assign(mouse.begin() + static_cast<std::ptrdiff_t>(i), mouse.end());
            break;
        }
        button_changed = button_changed || is_button;
        apply(mouse[i]);
    }
    return passed;
}

void ImGuiLayer::begin_frame(int width_px, int height_px, double seconds_since_last) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width_px), static_cast<float>(height_px));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    io.DeltaTime = seconds_since_last > 0.0 ? static_cast<float>(seconds_since_last) : 1.0f / 60.0f;
    width_px_ = width_px;
    height_px_ = height_px;
    ImGui::NewFrame();
}

frustum::Status ImGuiLayer::end_frame() {
    ImGui::Render();
    return painter_.draw(*ImGui::GetDrawData(), width_px_, height_px_);
}

} // namespace window
