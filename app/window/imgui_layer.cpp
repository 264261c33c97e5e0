#include "window/imgui_layer.hpp"

#include <imgui.h>

#include <type_traits>
#include <utility>
#include <variant>

namespace window {
namespace {

// The window's keys a text field uses -> io.KeysDown indices.
constexpr std::pair<ImGuiKey_, int> kTextKeys[] = {
    {ImGuiKey_Backspace, 1}, {ImGuiKey_Enter, 2},  {ImGuiKey_LeftArrow, 3},
    {ImGuiKey_RightArrow, 4}, {ImGuiKey_Escape, 5}, {ImGuiKey_Home, 6},
};

// The io.KeysDown index of a key a text field uses; -1 for the others.
int text_key_index(gl::Key key) {
    switch (key) {
    case gl::Key::Backspace: return 1;
    case gl::Key::Enter: return 2;
    case gl::Key::Left: return 3;
    case gl::Key::Right: return 4;
    case gl::Key::Escape: return 5;
    case gl::Key::Home: return 6;
    default: return -1;
    }
}

} // namespace

ImGuiLayer::ImGuiLayer(ImGuiContext* context, ImGuiPainter painter)
    : context_(context), painter_(std::move(painter)) {}

ImGuiLayer::~ImGuiLayer() { ImGui::DestroyContext(context_); }

frustum::Result<std::unique_ptr<ImGuiLayer>> ImGuiLayer::create(const gl::Functions& fn) {
    ImGuiContext* context = ImGui::CreateContext();
    ImGui::SetCurrentContext(context);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini: a run does not depend on the last one
    io.LogFilename = nullptr;
    // The keys a text field edits with, as io.KeysDown indices (ImGui 1.86's key map).
    for (const auto& [key, index] : kTextKeys) {
        io.KeyMap[key] = index;
    }
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
        keys_waiting_.clear();
        ImGuiIO& io = ImGui::GetIO();
        for (bool& down : io.MouseDown) {
            down = false;
        }
        return events;
    }
    ImGuiIO& io = ImGui::GetIO();
    const bool captured = io.WantCaptureMouse;
    // While a text field is being edited the keyboard is its own: the
    // characters and its keys go to ImGui, nothing to the window's keys.
    std::vector<gl::InputEvent> keys = std::move(keys_waiting_);
    keys_waiting_.clear();
    for (bool& down : io.KeysDown) {
        down = false; // a key is down for the one frame after its press
    }
    std::vector<gl::InputEvent> passed;
    std::vector<gl::InputEvent> mouse = std::move(waiting_);
    waiting_.clear();
    for (gl::InputEvent& event : events) {
        const bool is_key = std::holds_alternative<gl::KeyPressed>(event) || std::holds_alternative<gl::TextEntered>(event);
        if (is_key && io.WantTextInput) {
            keys.push_back(std::move(event));
            continue;
        }
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
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (const auto* typed = std::get_if<gl::TextEntered>(&keys[i])) {
            io.AddInputCharacter(typed->codepoint);
            continue;
        }
        const int index = text_key_index(std::get<gl::KeyPressed>(keys[i]).key);
        if (index >= 0 && io.KeysDown[index]) { // pressed twice in one frame: the second waits
            keys_waiting_.assign(keys.begin() + static_cast<std::ptrdiff_t>(i), keys.end());
            break;
        }
        if (index >= 0) {
            io.KeysDown[index] = true;
        }
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
